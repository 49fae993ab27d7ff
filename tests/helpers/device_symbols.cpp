// device_symbols.cpp - file-scope names of an OpenCL C source: comments are
// dropped, `#define` lines give macro names, and the remaining code is
// walked token by token at brace depth 0 (function and struct bodies and
// parameter lists are skipped, enum bodies read for their enumerators).
#include "device_symbols.hpp"

#include <cctype>
#include <sstream>

namespace ggxtest {

namespace {

// `source` with comments replaced by spaces (newlines kept) and string and
// character literals kept as they are.
std::string without_comments(const std::string& source)
{
    std::string out;
    for (std::size_t k = 0; k < source.size(); ++k) {
        char c = source[k], next = k + 1 < source.size() ? source[k + 1] : '\0';
        if (c == '/' && next == '/') {
            while (k < source.size() && source[k] != '\n')
                ++k;
            out += '\n';
        } else if (c == '/' && next == '*') {
            for (k += 2; k + 1 < source.size() && !(source[k] == '*' && source[k + 1] == '/'); ++k)
                out += source[k] == '\n' ? '\n' : ' ';
            ++k;
        } else if (c == '"' || c == '\'') {
            out += c;
            for (++k; k < source.size() && source[k] != c; ++k) {
                if (source[k] == '\\')
                    out += source[k++];
                out += source[k];
            }
            out += c;
        } else {
            out += c;
        }
    }
    return out;
}

bool is_identifier_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// "NAME" of "NAME(x)".
std::string leading_identifier(const std::string& word)
{
    std::size_t end = 0;
    while (end < word.size() && is_identifier_char(word[end]))
        ++end;
    return word.substr(0, end);
}

// Macro names of the #define lines; the other lines (continuations joined) are code.
void split_directives(const std::string& text, std::vector<std::string>& macros, std::string& code)
{
    std::istringstream lines(text);
    std::string line, logical;
    while (std::getline(lines, line)) {
        logical += line;
        if (!logical.empty() && logical.back() == '\\') {
            logical.back() = ' ';
            continue;
        }
        std::istringstream words(logical);
        std::string first, directive, name;
        words >> first;
        if (!first.empty() && first[0] == '#') {
            directive = first.substr(1);
            if (directive.empty())
                words >> directive;  // "# define"
            if (directive == "define" && words >> name)
                macros.push_back(leading_identifier(name));
        } else {
            code += logical + "\n";
        }
        logical.clear();
    }
}

// Identifiers and single-character punctuation; literals become one token "0".
std::vector<std::string> tokens_of(const std::string& code)
{
    std::vector<std::string> tokens;
    for (std::size_t k = 0; k < code.size();) {
        char c = code[k];
        if (std::isspace(static_cast<unsigned char>(c))) {
            ++k;
        } else if (is_identifier_start(c)) {
            std::size_t start = k;
            while (k < code.size() && is_identifier_char(code[k]))
                ++k;
            tokens.push_back(code.substr(start, k - start));
        } else if (std::isdigit(static_cast<unsigned char>(c)) || c == '"' || c == '\'') {
            char quote = std::isdigit(static_cast<unsigned char>(c)) ? '\0' : c;
            for (++k; k < code.size(); ++k) {
                if (quote ? code[k] == quote : !(is_identifier_char(code[k]) || code[k] == '.'))
                    break;
                if (quote && code[k] == '\\')
                    ++k;
            }
            k += quote ? 1 : 0;
            tokens.push_back("0");
        } else {
            tokens.push_back(std::string(1, c));
            ++k;
        }
    }
    return tokens;
}

bool is_identifier(const std::string& token) { return !token.empty() && is_identifier_start(token[0]); }

// Names declared by the file-scope statements of `tokens`.
class FileScopeWalker {
public:
    std::vector<std::string> names;

    void walk(const std::vector<std::string>& tokens)
    {
        for (std::size_t k = 0; k < tokens.size(); ++k)
            step(tokens[k], k + 1 < tokens.size() ? tokens[k + 1] : "");
    }

private:
    int braces_ = 0, parens_ = 0;
    bool typedef_ = false, function_ = false, enum_body_ = false, expect_enumerator_ = false;
    std::string last_;  // the last identifier at file scope

    void step(const std::string& token, const std::string& next)
    {
        if (braces_ > 0 || parens_ > 0)
            return inside(token);
        if (token == "typedef")
            typedef_ = true;
        else if ((token == "struct" || token == "union" || token == "enum") && is_identifier(next) && next != "{")
            names.push_back(next);
        if (token == "enum")
            enum_body_ = true;
        if (is_identifier(token))
            last_ = token;
        else
            punctuation(token);
    }

    void punctuation(const std::string& token)
    {
        if (token == "(") {
            if (!typedef_ && !function_ && declarable(last_)) {
                names.push_back(last_);
                function_ = true;
            }
            ++parens_;
        } else if (token == "{") {
            ++braces_;
            expect_enumerator_ = enum_body_;
            last_.clear();  // a tag before a body is already recorded
        } else if (token == "=" || token == "[" || token == "," || token == ";") {
            if (!function_ && declarable(last_))
                names.push_back(last_);
            if (token == ";")
                end_statement();
            last_.clear();
        }
    }

    // Inside braces or parentheses: only depths and enumerators matter.
    void inside(const std::string& token)
    {
        parens_ += token == "(" ? 1 : token == ")" ? -1 : 0;
        braces_ += token == "{" ? 1 : 0;
        if (token == "}" && --braces_ == 0) {
            enum_body_ = false;
            if (function_)
                end_statement();  // a function body ends its definition
            return;
        }
        if (enum_body_ && braces_ == 1 && parens_ == 0) {
            if (expect_enumerator_ && is_identifier(token))
                names.push_back(token);
            expect_enumerator_ = token == ",";
        }
    }

    void end_statement()
    {
        typedef_ = function_ = enum_body_ = false;
        last_.clear();
    }

    // Names a declaration can introduce: not reserved (__kernel, __attribute__, ...), not the
    // shading languages' qualifiers and attributes (GLSL `layout(...) in`, HLSL `[[vk::binding(...)]]`),
    // nor empty.
    static bool declarable(const std::string& name)
    {
        static const char* qualifiers[] = {"layout", "in", "binding", "push_constant", "numthreads"};
        for (const char* q : qualifiers)
            if (name == q)
                return false;
        return !name.empty() && name.rfind("__", 0) != 0;
    }
};

} // namespace

std::vector<std::string> defined_names(const std::string& source)
{
    std::vector<std::string> names;
    std::string code;
    split_directives(without_comments(source), names, code);
    FileScopeWalker walker;
    walker.walk(tokens_of(code));
    names.insert(names.end(), walker.names.begin(), walker.names.end());
    return names;
}

std::vector<std::string> unprefixed_names(const std::string& source)
{
    std::vector<std::string> out;
    for (const std::string& name : defined_names(source))
        if (name.rfind("ggx_", 0) != 0 && name.rfind("GGX_", 0) != 0)
            out.push_back(name);
    return out;
}

} // namespace ggxtest
