#!/usr/bin/env bash
# Installs every Debian 12 package that building, running and testing Camwright needs.
# Idempotent: quiet and quick when everything is already present.
set -euo pipefail

packages=(
    # toolchain (git: .ci/check-format lists the sources with git ls-files)
    build-essential cmake ninja-build pkg-config git
    # the sanitizer and fuzzing builds (the debug and fuzz presets): clang with its runtimes;
    # clang-format, whose style .ci/check-format enforces
    clang libclang-rt-14-dev clang-format
    # libraries
    qt6-base-dev qt6-base-dev-tools qt6-svg-dev qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools
    libqt6svg6 qt6-qpa-plugins libgl-dev
    # Qt's own strings in German (dialog buttons, file dialogs, key names)
    qt6-translations-l10n
    libqcustomplot-dev libqcustomplot2.1-qt6
    libeigen3-dev nlohmann-json3-dev
    # tests and benchmarks
    libgtest-dev libgmock-dev googletest libbenchmark-dev
    python3 python3-mpmath python3-numpy python3-ezdxf python3-svgelements
    # the programs that read exports in the tests: LinuxCNC's rs274 (tests/tools/rs274 unpacks
    # Debian's linuxcnc-uspace below) needs these libraries; poppler (pdfinfo, pdftotext,
    # pdftoppm) and rsvg-convert read the pictures of the plots
    libboost-python1.74.0 libpython3.11 poppler-utils librsvg2-bin
    # headless rendering needs real fonts
    fonts-dejavu-core
    # a real X display and input for the crash-recovery test (app_tests CrashRecovery.*)
    xvfb xdotool
    # the DEB package and Debian's checks of it (packaging.DebPackage)
    dpkg-dev file lintian desktop-file-utils appstream
)

missing=()
for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$p")
    fi
done
if [ ${#missing[@]} -gt 0 ]; then
    echo "install-deps: installing ${missing[*]}" >&2
    sudo_cmd=()
    [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
    export DEBIAN_FRONTEND=noninteractive
    "${sudo_cmd[@]}" apt-get update -qq
    "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# LinuxCNC's G-code interpreter for the G-code tests: Debian's package unpacked into the user's
# cache, not installed (quick when it is already there).
bash "$(dirname "$0")/../tests/tools/rs274" --install
