#include "export/free_text.h"

#include <cstdint>
#include <vector>

namespace cam {
namespace {

constexpr char32_t kReplacement = 0xFFFD;

/// The code points of `text` (with `invalid` counting the bytes that are not UTF-8), each invalid
/// or incomplete UTF-8 sequence (overlong forms, surrogates and values above U+10FFFF included) one
/// U+FFFD per byte.
std::vector<char32_t> decode(std::string_view text, std::size_t* invalid = nullptr) {
    std::vector<char32_t> out;
    out.reserve(text.size());
    std::size_t i = 0;
    while (i < text.size()) {
        const auto b0 = static_cast<unsigned char>(text[i]);
        std::size_t length = 0;
        char32_t c = 0;
        char32_t least = 0;
        if (b0 < 0x80) {
            out.push_back(b0);
            ++i;
            continue;
        }
        if ((b0 & 0xE0) == 0xC0) {
            length = 2, c = b0 & 0x1F, least = 0x80;
        } else if ((b0 & 0xF0) == 0xE0) {
            length = 3, c = b0 & 0x0F, least = 0x800;
        } else if ((b0 & 0xF8) == 0xF0) {
            length = 4, c = b0 & 0x07, least = 0x10000;
        }
        bool valid = length > 0 && i + length <= text.size();
        for (std::size_t k = 1; valid && k < length; ++k) {
            const auto b = static_cast<unsigned char>(text[i + k]);
            valid = (b & 0xC0) == 0x80;
            c = (c << 6) | (b & 0x3F);
        }
        valid = valid && c >= least && c <= 0x10FFFF && !(c >= 0xD800 && c <= 0xDFFF);
        if (!valid) {
            if (invalid) ++*invalid;
            out.push_back(kReplacement);
            ++i;
            continue;
        }
        out.push_back(c);
        i += length;
    }
    return out;
}

void encode(std::string& out, char32_t c) {
    if (c < 0x80) {
        out += static_cast<char>(c);
    } else if (c < 0x800) {
        out += static_cast<char>(0xC0 | (c >> 6));
        out += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
        out += static_cast<char>(0xE0 | (c >> 12));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (c & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (c >> 18));
        out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (c & 0x3F));
    }
}

bool isControl(char32_t c) {
    return c < 0x20 || (c >= 0x7F && c <= 0x9F) || c == 0x2028 || c == 0x2029;
}

bool isDropped(char32_t c) {
    const bool bidi = c == 0x061C || c == 0x200E || c == 0x200F || (c >= 0x202A && c <= 0x202E) ||
                      (c >= 0x2066 && c <= 0x2069);
    const bool nonCharacter = (c >= 0xFDD0 && c <= 0xFDEF) || (c & 0xFFFE) == 0xFFFE;
    return bidi || nonCharacter || c == 0xFEFF;
}

}  // namespace

bool isValidUtf8(std::string_view text) {
    std::size_t invalid = 0;
    decode(text, &invalid);
    return invalid == 0;
}

std::string oneLine(std::string_view text, std::size_t maxChars) {
    std::vector<char32_t> kept;
    for (char32_t c : decode(text)) {
        if (isDropped(c)) continue;
        kept.push_back(isControl(c) ? U' ' : c);
    }
    std::size_t begin = 0, end = kept.size();
    while (begin < end && kept[begin] == U' ') ++begin;
    while (end > begin && kept[end - 1] == U' ') --end;
    const bool cut = end - begin > maxChars;
    if (cut) end = begin + (maxChars > 0 ? maxChars - 1 : 0);
    std::string out;
    for (std::size_t i = begin; i < end; ++i) encode(out, kept[i]);
    if (cut && maxChars > 0) encode(out, U'…');
    return out;
}

std::string xmlText(std::string_view text, std::size_t maxChars) {
    std::string out;
    for (char c : oneLine(text, maxChars)) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&apos;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

std::string csvCommentText(std::string_view text, std::size_t maxChars) {
    std::string out;
    bool cellStart = true;  // no character of the current cell but spaces yet
    for (char c : oneLine(text, maxChars)) {
        if (c == '"') c = '\'';
        if (cellStart && (c == '=' || c == '+' || c == '-' || c == '@')) out += '\'';
        if (c != ' ') cellStart = false;
        if (c == ',' || c == ';') cellStart = true;
        out += c;
    }
    return out;
}

}  // namespace cam
