# ctest script: installs the build into a fresh prefix and checks what a user gets there — both
# programs, every bundled example — and that the installed CLI reads an installed example.
#   cmake -DBUILD_DIR=… -DPREFIX=… -DBINDIR=… -DDATADIR=… -DEXAMPLES=<source folder> -DAPP=ON|OFF
#         -P install_layout.cmake
cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "cmake --install failed (${rc}):\n${out}${err}")
endif()

set(expected "${BINDIR}/camwright-cli")
if(APP)
    list(APPEND expected "${BINDIR}/camwright")
endif()
file(GLOB examples RELATIVE "${EXAMPLES}" "${EXAMPLES}/*.cam.json")
if(NOT examples)
    message(FATAL_ERROR "no examples in ${EXAMPLES}")
endif()
foreach(example ${examples})
    list(APPEND expected "${DATADIR}/camwright/examples/${example}")
endforeach()
foreach(file ${expected})
    if(NOT EXISTS "${PREFIX}/${file}")
        message(FATAL_ERROR "not installed: ${PREFIX}/${file}")
    endif()
endforeach()

execute_process(
    COMMAND "${PREFIX}/${BINDIR}/camwright-cli" validate
            "${PREFIX}/${DATADIR}/camwright/examples/six-lobe-arc-cam.cam.json"
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out STREQUAL "valid: 13 segments\n")
    message(FATAL_ERROR "the installed camwright-cli: exit ${rc}\n${out}${err}")
endif()
file(REMOVE_RECURSE "${PREFIX}")
message(STATUS "installed and checked: ${expected}")
