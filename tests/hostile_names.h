#pragma once
// The hostile-name corpus of issue 27: the 29 kinds of project (and file) name a reliability
// probe sent into every export. Each must leave every export valid in the program that reads
// it. Kept here, in the tests, so a new export format is run through all of them.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "test_support.h"

namespace cam::test {

struct HostileName {
    const char* kind;  ///< what it tries, for a failure's message
    std::string text;
};

/// The checker that reads exports carrying such names with their consumers.
inline std::string freeTextChecker() {
    return std::string(CAMWRIGHT_SOURCE_DIR) + "/tests/reference/check_free_text.py";
}

/// Runs freeTextChecker on every export in `folder`, G-code through LinuxCNC's rs274 too:
/// success, or the problems it found, or that not `files` files were checked.
inline ::testing::AssertionResult exportsAreValid(const std::string& folder, std::size_t files) {
    const std::vector<std::string> args{freeTextChecker(), folder, "--points", "360",
                                        "--rs274",         kRs274};
    const auto r = run("/usr/bin/python3", args, 600);
    if (r.exitCode != 0) return ::testing::AssertionFailure() << r.out << r.err;
    if (r.err.find(std::to_string(files) + " files checked") == std::string::npos)
        return ::testing::AssertionFailure() << "not " << files << " files: " << r.err;
    return ::testing::AssertionSuccess();
}

inline std::vector<HostileName> hostileNames() {
    using namespace std::string_literals;
    return {
        {"parentheses", "Cam (left) ) ((right"},
        {"newline with M30", "cam\nM30\n(end of program"},
        {"percent", "%\n100 % cam %"},
        {"semicolon", "cam; M30 ; x"},
        {"script tag", "<script>alert('x')</script>"},
        {"ampersand", "Cams & Co. &amp; &#0; &bogus;"},
        {"CDATA end", "a]]>b<![CDATA[c"},
        {"quotes", "\"quoted\" 'single' \"open"},
        {"leading =", "=HYPERLINK(\"http://x.example\",\"click\")"},
        {"leading @", "@SUM(1+1)*cmd|' /C calc'!A0"},
        {"tab", "a\tb\t=1+1\t-2"},
        {"NUL", "before\0after"s},
        {"C0 controls", "\x01\x02\x07\x08\x0b\x0c\x1b[31mred\x1b[0m\x7f"},
        {"CR", "cam\r=1+1\rx"},
        {"100,000 characters", std::string(100000, 'W')},
        {"RLO and RLM", "\u202Egnp.exe\u200F cam"},
        {"emoji", "Cam \U0001F680 \u2699\uFE0F \U0001F600"},
        {"U+FFFE", "a\uFFFEb\uFFFF"},
        {"END_VAR", "END_VAR"},
        {"TRUE", "TRUE"},
        {"ST comment", "(* nested (* comment *) *) *)"},
        {"digits", "12345"},
        {"DXF group codes", "0\nEOF\n999\ninjected\n0\nSECTION"},
        {"leading +", "+1+2"},
        {"leading -", "-2-3"},
        {"comma and formula", "left,=1+1, @A1,;-cmd"},
        {"line separators",
         "a\u2028b\u2029c\xC2\x85"
         "d\r\n\r\n"},
        {"byte-order mark and bidi isolates", "\uFEFF\u2066x\u2069\u061C"},
        {"spaces only", "   "},
    };
}

}  // namespace cam::test
