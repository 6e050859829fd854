# ctest script: builds the DEB with CPack into a fresh folder and checks it as Debian would —
# lintian without errors, the desktop entry and the AppStream file valid, and every file a
# user's desktop needs inside the package.
#   cmake -DBUILD_DIR=… -DOUT=… -DSOURCE_DIR=… -P deb_package.cmake
cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
execute_process(COMMAND cpack --config "${BUILD_DIR}/CPackConfig.cmake" -B "${OUT}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "cpack failed (${rc}):\n${out}${err}")
endif()
file(GLOB debs "${OUT}/camwright_*.deb")
list(LENGTH debs count)
if(NOT count EQUAL 1)
    message(FATAL_ERROR "expected one camwright_*.deb in ${OUT}, found: ${debs}")
endif()

execute_process(COMMAND dpkg-deb -c "${debs}" OUTPUT_VARIABLE listing RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "dpkg-deb -c failed")
endif()
foreach(file
        ./usr/bin/camwright ./usr/bin/camwright-cli
        ./usr/share/applications/org.camwright.Camwright.desktop
        ./usr/share/metainfo/org.camwright.Camwright.metainfo.xml
        ./usr/share/mime/packages/org.camwright.Camwright.xml
        ./usr/share/icons/hicolor/scalable/apps/org.camwright.Camwright.svg
        ./usr/share/icons/hicolor/48x48/apps/org.camwright.Camwright.png
        ./usr/share/icons/hicolor/256x256/apps/org.camwright.Camwright.png
        ./usr/share/man/man1/camwright.1.gz ./usr/share/man/man1/camwright-cli.1.gz
        ./usr/share/doc/camwright/copyright ./usr/share/doc/camwright/changelog.gz
        ./usr/share/camwright/examples/six-lobe-arc-cam.cam.json)
    string(FIND "${listing}" " ${file}\n" at)
    if(at EQUAL -1)
        message(FATAL_ERROR "not in the package: ${file}\n${listing}")
    endif()
endforeach()
execute_process(COMMAND dpkg-deb -f "${debs}" Depends OUTPUT_VARIABLE depends)
foreach(dependency qt6-qpa-plugins libqt6widgets6 libqcustomplot2.1-qt6)
    string(FIND "${depends}" "${dependency}" at)
    if(at EQUAL -1)
        message(FATAL_ERROR "the package does not depend on ${dependency}: ${depends}")
    endif()
endforeach()

# Debian's own checkers. lintian exits non-zero on an error (warnings are reported too).
execute_process(COMMAND lintian --fail-on error,warning "${debs}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "lintian (${rc}):\n${out}${err}")
endif()
execute_process(
    COMMAND desktop-file-validate
            "${SOURCE_DIR}/packaging/linux/org.camwright.Camwright.desktop"
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT "${out}${err}" STREQUAL "")
    message(FATAL_ERROR "desktop-file-validate (${rc}):\n${out}${err}")
endif()
execute_process(
    COMMAND appstreamcli validate --no-net
            "${SOURCE_DIR}/packaging/linux/org.camwright.Camwright.metainfo.xml"
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "appstreamcli validate (${rc}):\n${out}${err}")
endif()
file(REMOVE_RECURSE "${OUT}")
message(STATUS "${debs}: lintian, desktop-file-validate and appstreamcli clean")
