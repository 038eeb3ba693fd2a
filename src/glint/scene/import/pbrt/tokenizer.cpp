#include <glint/core/error.h>
#include <glint/scene/import/pbrt/tokenizer.h>

#include <fmt/format.h>

namespace glint {
namespace {

bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

// A word ends where a string, a bracket, a comment or white space begins.
bool ends_word(char c) {
    return is_space(c) || c == '"' || c == '[' || c == ']' || c == '#';
}

}  // namespace

void PbrtTokenizer::fail(int line, const std::string& what) const {
    throw Error(fmt::format("{}:{}: {}", m_file, line, what));
}

void PbrtTokenizer::skip_space_and_comments() {
    while (m_pos < m_text.size()) {
        const char c = m_text[m_pos];
        if (c == '\n') {
            ++m_line;
            ++m_pos;
        } else if (is_space(c)) {
            ++m_pos;
        } else if (c == '#') {
            while (m_pos < m_text.size() && m_text[m_pos] != '\n') ++m_pos;
        } else {
            return;
        }
    }
}

PbrtToken PbrtTokenizer::read_string() {
    PbrtToken token{PbrtToken::Kind::String, {}, m_line};
    ++m_pos;  // the opening quote
    while (true) {
        if (m_pos >= m_text.size()) fail(token.line, "unterminated string (no closing '\"')");
        const char c = m_text[m_pos++];
        if (c == '"') return token;
        if (c == '\n') fail(token.line, "unterminated string (a newline before the closing '\"')");
        if (c != '\\') {
            token.text.push_back(c);
            continue;
        }
        if (m_pos >= m_text.size()) fail(token.line, "unterminated string (ends in '\\')");
        const char e = m_text[m_pos++];
        switch (e) {
            case 'n':
                token.text.push_back('\n');
                break;
            case 't':
                token.text.push_back('\t');
                break;
            case 'r':
                token.text.push_back('\r');
                break;
            case 'b':
                token.text.push_back('\b');
                break;
            case 'f':
                token.text.push_back('\f');
                break;
            case '\\':
                token.text.push_back('\\');
                break;
            case '"':
                token.text.push_back('"');
                break;
            case '\'':
                token.text.push_back('\'');
                break;
            default:
                fail(m_line, fmt::format("unknown escape '\\{}' in a string", e));
        }
    }
}

PbrtToken PbrtTokenizer::next() {
    skip_space_and_comments();
    if (m_pos >= m_text.size()) return PbrtToken{PbrtToken::Kind::End, {}, m_line};
    const char c = m_text[m_pos];
    if (c == '"') return read_string();
    if (c == '[' || c == ']') {
        ++m_pos;
        return PbrtToken{c == '[' ? PbrtToken::Kind::Open : PbrtToken::Kind::Close,
                         std::string(1, c), m_line};
    }
    const size_t start = m_pos;
    while (m_pos < m_text.size() && !ends_word(m_text[m_pos])) ++m_pos;
    return PbrtToken{PbrtToken::Kind::Word, m_text.substr(start, m_pos - start), m_line};
}

}  // namespace glint
