#pragma once
// The lexical layer of pbrt-v4's scene format: bare words (directives, numbers, true/false),
// quoted strings, '[' and ']', with '#' comments to the end of the line. Every token knows
// its line, so that each later message can name the file and line it came from.
#include <string>

namespace glint {

/// One token of a pbrt file.
struct PbrtToken {
    enum class Kind { Word, String, Open, Close, End };
    Kind kind = Kind::End;
    std::string text;  ///< the word, or the string without its quotes (escapes resolved)
    int line = 0;      ///< 1-based
};

/// Splits the text of one file into tokens. Throws glint::Error "file:line: ..." for an
/// unterminated string, a newline inside a string or an unknown escape.
class PbrtTokenizer {
public:
    PbrtTokenizer(std::string text, std::string file)
        : m_text(std::move(text)), m_file(std::move(file)) {}

    /// The next token; Kind::End (repeatedly) at the end of the text.
    PbrtToken next();
    const std::string& file() const { return m_file; }

private:
    void skip_space_and_comments();
    PbrtToken read_string();
    [[noreturn]] void fail(int line, const std::string& what) const;

    std::string m_text;
    std::string m_file;
    size_t m_pos = 0;
    int m_line = 1;
};

}  // namespace glint
