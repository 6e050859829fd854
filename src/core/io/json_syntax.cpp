#include "io/json_syntax.h"

#include <algorithm>
#include <unordered_set>
#include <vector>

namespace cam {
namespace {

/// At most this many characters of a token are quoted in a message.
constexpr std::size_t kQuotedChars = 40;

std::string quotedToken(std::string_view token) {
    // Cut at kQuotedChars bytes, but never inside a UTF-8 character or inside one of the
    // "<U+0009>" escapes nlohmann writes for control characters.
    std::size_t cut = std::min(token.size(), kQuotedChars);
    while (cut > 0 && cut < token.size() &&
           (static_cast<unsigned char>(token[cut]) & 0xC0) == 0x80) {
        --cut;
    }
    if (const std::size_t open = token.substr(0, cut).rfind("<U+");
        open != std::string_view::npos && cut < token.size() &&
        token.substr(open, cut - open).find('>') == std::string_view::npos) {
        cut = open;
    }
    std::string out = "'";
    for (char c : token.substr(0, cut)) {
        // Control characters would garble a terminal or a message box: show them escaped.
        if (static_cast<unsigned char>(c) < 0x20) {
            static const char* hex = "0123456789abcdef";
            out += "\\x";
            out += hex[(c >> 4) & 0xf];
            out += hex[c & 0xf];
        } else {
            out += c;
        }
    }
    if (cut < token.size()) out += "…";
    return out + "'";
}

/// Builds the DOM from the parser's events, like nlohmann's own DOM parser, and also names
/// duplicated keys and too deep nesting by their JSON path, and locates syntax errors by the
/// parser's byte position. Everything is linear in the size of the text.
class LocatingDomBuilder : public nlohmann::json_sax<Json> {
public:
    LocatingDomBuilder(std::string_view text, Json& root) : m_text(text), m_root(root) {}

    [[nodiscard]] const Diagnostics& problems() const { return m_problems; }

    bool null() override { return value(nullptr); }
    bool boolean(bool v) override { return value(v); }
    bool number_integer(number_integer_t v) override { return value(v); }
    bool number_unsigned(number_unsigned_t v) override { return value(v); }
    bool number_float(number_float_t v, const string_t&) override { return value(v); }
    bool string(string_t& v) override { return value(std::move(v)); }
    bool binary(binary_t& v) override { return value(std::move(v)); }

    bool start_object(std::size_t) override { return open(Json::object(), false); }
    bool start_array(std::size_t) override { return open(Json::array(), true); }
    bool end_object() override { return close(); }
    bool end_array() override { return close(); }

    bool key(string_t& key) override {
        Frame& f = m_frames.back();
        f.key = key;
        if (!f.keys.insert(key).second) {
            m_problems.push_back(
                Diagnostic::make(FileKeyPlace{path()}, DiagnosticCode::JsonDuplicatedKey));
            return false;
        }
        // The key is new, so append without ordered_map's linear search for it.
        auto& entries =
            static_cast<Json::object_t::Container&>(m_stack.back()->get_ref<Json::object_t&>());
        entries.emplace_back(std::move(key), nullptr);
        m_member = &entries.back().second;
        return true;
    }

    bool parse_error(std::size_t position, const std::string& lastToken,
                     const Json::exception& ex) override {
        if (ex.id == 406) {  // a number beyond the range of a double: point at its first digit
            const std::size_t start =
                position >= lastToken.size() ? position - lastToken.size() : 0;
            m_problems.push_back(Diagnostic::make(filePosition(m_text, start),
                                                  DiagnosticCode::JsonNumberTooLarge,
                                                  {quotedToken(lastToken)}));
            return false;
        }
        // nlohmann's message reads "[json.exception.parse_error.101] parse error at line L,
        // column C: <reason>; last read: '<token>'": keep the reason, quote the token ourselves
        // (it can be megabytes long), and take the place from the byte position.
        const std::string what = ex.what();
        const std::size_t column = what.find("column ");
        const std::size_t colon = column == std::string::npos ? column : what.find(": ", column);
        std::string reason = colon == std::string::npos ? "syntax error" : what.substr(colon + 2);
        const std::size_t last = reason.find("; last read: ");
        if (last != std::string::npos) reason.resize(last);
        if (!lastToken.empty()) reason += "; last read: " + quotedToken(lastToken);
        const std::size_t at = position > 0 ? position - 1 : 0;
        m_problems.push_back(
            Diagnostic::make(filePosition(m_text, at), DiagnosticCode::JsonSyntax, {reason}));
        return false;
    }

private:
    struct Frame {
        bool isArray = false;
        std::size_t index = 0;
        std::string key;
        std::unordered_set<std::string> keys;
    };

    /// Where the value now being read goes: the root, the next array element or the member
    /// whose key was just read.
    Json* slot() {
        if (m_stack.empty()) return &m_root;
        Json* top = m_stack.back();
        if (top->is_array()) {
            top->get_ref<Json::array_t&>().emplace_back();
            return &top->get_ref<Json::array_t&>().back();
        }
        return m_member;
    }

    template <class V>
    bool value(V&& v) {
        *slot() = Json(std::forward<V>(v));
        advance();
        return true;
    }

    bool open(Json container, bool isArray) {
        if (m_frames.size() >= static_cast<std::size_t>(kMaxJsonDepth)) {
            m_problems.push_back(Diagnostic::make(FileKeyPlace{path()}, DiagnosticCode::JsonTooDeep,
                                                  {static_cast<double>(kMaxJsonDepth)}));
            return false;
        }
        Json* at = slot();
        *at = std::move(container);
        m_stack.push_back(at);
        m_frames.push_back({isArray, 0, {}, {}});
        return true;
    }

    bool close() {
        m_stack.pop_back();
        m_frames.pop_back();
        advance();
        return true;
    }

    void advance() {
        if (!m_frames.empty() && m_frames.back().isArray) ++m_frames.back().index;
    }

    std::string path() const {
        // Deep paths are named by their first levels only: "key[0][0][0]…".
        constexpr std::size_t kShownLevels = 4;
        std::string p;
        for (std::size_t i = 0; i < m_frames.size(); ++i) {
            const Frame& f = m_frames[i];
            if (i == kShownLevels) {
                p += "…";
                break;
            }
            if (f.isArray) {
                p += '[';  // appends: GCC 12 warns falsely on "[" + string (PR105651)
                p += std::to_string(f.index);
                p += ']';
            } else if (!f.key.empty()) {
                if (!p.empty()) p += '.';
                p += f.key;
            }
        }
        return p.empty() ? "(top level)" : p;
    }

    std::string_view m_text;
    Json& m_root;
    std::vector<Json*> m_stack;
    std::vector<Frame> m_frames;
    Json* m_member = nullptr;
    Diagnostics m_problems;
};

}  // namespace

FilePositionPlace filePosition(std::string_view text, std::size_t offset) {
    offset = std::min(offset, text.size());
    std::size_t line = 1, lineStart = 0;
    for (std::size_t i = 0; i < offset; ++i) {
        if (text[i] == '\n') {
            ++line;
            lineStart = i + 1;
        }
    }
    return {line, offset - lineStart + 1};
}

Diagnostics parseJson(std::string_view text, Json& out) {
    // nlohmann's lexer takes a NUL for the end of the input and would ignore what follows.
    if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos) {
        return {Diagnostic::make(filePosition(text, nul), DiagnosticCode::JsonNulByte,
                                 {static_cast<double>(nul)})};
    }
    out = Json();
    LocatingDomBuilder builder(text, out);
    const bool ok = Json::sax_parse(text.begin(), text.end(), &builder);
    if (ok) return {};
    Diagnostics problems = builder.problems();
    if (problems.empty()) {
        problems.push_back(
            Diagnostic::make(FileKeyPlace{"(top level)"}, DiagnosticCode::JsonInvalid));
    }
    out = Json();
    return problems;
}

}  // namespace cam
