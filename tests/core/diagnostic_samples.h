#pragma once
// A diagnostic of every code with sample arguments, each recognisable in the text, for the
// tests that render the whole catalogue (the core's English, the window's languages).

#include <string>
#include <vector>

#include "common/diagnostic_catalogue.h"

namespace cam::test {

/// The sample argument of kind `kind` at position `i`: numbers 1000.25, 1001.25, …; whole
/// numbers 71, 72, …; one-decimal numbers 12.5, 13.5, …; segments 40, 41, …; axis z; the
/// field phi_start; names «s0», «s1», …; texts «t0», …; the law cycloidal.
inline DiagnosticArg sampleArgument(char kind, int i) {
    switch (kind) {
        case 'n':
            return 1000.25 + i;
        case 'i':
            return 71.0 + i;
        case 'd':
            return 12.5 + i;
        case 'k':
            return 40.0 + i;
        case 'a':
            return 2.0;
        case 'f':
            return SegmentPart::PhiStart;
        case 's':
            return "«s" + std::to_string(i) + "»";
        case 'l':
            return std::string("cycloidal");
        default:
            return "«t" + std::to_string(i) + "»";
    }
}

/// The code's sample arguments, as its signature lists them (`r` takes none).
inline std::vector<DiagnosticArg> sampleArguments(DiagnosticCode code) {
    std::vector<DiagnosticArg> args;
    int i = 0;
    for (const char kind : diagnosticCodeSignature(code)) {
        if (kind != 'r') args.push_back(sampleArgument(kind, i));
        ++i;
    }
    return args;
}

/// The reason a sample lists where its code lists reasons.
inline Diagnostic sampleReason() {
    return Diagnostic::make(SegmentPlace{2, SegmentPart::Radius}, DiagnosticCode::NotPositive,
                            {-2.5});
}

/// The code with its sample arguments, at a field, with a reason where it lists them.
inline Diagnostic sampleDiagnostic(DiagnosticCode code) {
    Diagnostic d = Diagnostic::make(FieldPlace{Field::MachiningStep}, code, sampleArguments(code));
    if (diagnosticCodeSignature(code).find('r') != std::string_view::npos) {
        d = std::move(d).because({sampleReason()});
    }
    return d;
}

}  // namespace cam::test
