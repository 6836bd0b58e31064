#include "dictionary.H"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace slide
{
namespace scene
{

namespace
{

std::string formatError(const std::string& file, int line, const std::string& key, const std::string& message)
{
    std::ostringstream os;
    os << file;
    if (line > 0) os << ':' << line;
    os << ": ";
    if (!key.empty()) os << "key '" << key << "': ";
    os << message;
    return os.str();
}

std::string qualified(const std::string& dictName, const std::string& key)
{
    return dictName.empty() ? key : dictName + "." + key;
}

// Levenshtein distance, for "did you mean" hints on unknown keys.
std::size_t editDistance(const std::string& a, const std::string& b)
{
    std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i)
    {
        cur[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j)
        {
            const std::size_t sub = prev[j - 1] + (std::tolower(a[i - 1]) == std::tolower(b[j - 1]) ? 0 : 1);
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, sub});
        }
        std::swap(prev, cur);
    }
    return prev[b.size()];
}

bool isPunctuation(char c)
{
    return c == '{' || c == '}' || c == '(' || c == ')' || c == '[' || c == ']' || c == ';';
}

} // namespace


InputError::InputError(const std::string& file, int line, const std::string& key, const std::string& message)
:
    std::runtime_error(formatError(file, line, key, message)),
    file_(file),
    line_(line),
    key_(key),
    message_(message)
{}


std::string Token::describe() const
{
    switch (kind)
    {
        case Kind::number: return "number " + text;
        case Kind::string: return "string \"" + text + "\"";
        case Kind::punctuation: return "'" + text + "'";
        default: return "word '" + text + "'";
    }
}

std::string Value::describe() const
{
    if (isList) return "a list of " + std::to_string(items.size()) + " items";
    if (!items.empty()) return std::to_string(items.size()) + " values";
    return token.describe();
}


// ---------------------------------------------------------------------------
class DictionaryParser
{
public:
    DictionaryParser(const std::string& text, const std::string& file)
    :
        file_(file)
    {
        tokenise(text);
    }

    Dictionary parseTop()
    {
        Dictionary top;
        top.file_ = file_;
        top.line_ = 1;
        parseEntries(top, /*closing*/ false, 0);
        return top;
    }

private:
    std::string file_;
    std::vector<Token> tokens_;
    std::size_t pos_ = 0;
    int lastLine_ = 1;

    [[noreturn]] void fail(int line, const std::string& key, const std::string& message) const
    {
        throw InputError(file_, line, key, message);
    }

    void tokenise(const std::string& s)
    {
        int line = 1;
        std::size_t i = 0;
        const std::size_t n = s.size();
        while (i < n)
        {
            const char c = s[i];
            if (c == '\n') { ++line; ++i; continue; }
            if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') { ++i; continue; }
            if (c == '/' && i + 1 < n && s[i + 1] == '/')
            {
                while (i < n && s[i] != '\n') ++i;
                continue;
            }
            if (c == '/' && i + 1 < n && s[i + 1] == '*')
            {
                const int start = line;
                i += 2;
                while (i + 1 < n && !(s[i] == '*' && s[i + 1] == '/'))
                {
                    if (s[i] == '\n') ++line;
                    ++i;
                }
                if (i + 1 >= n) fail(start, "", "unterminated /* comment */");
                i += 2;
                continue;
            }
            if (c == '"')
            {
                const int start = line;
                std::string text;
                ++i;
                while (i < n && s[i] != '"')
                {
                    if (s[i] == '\n') fail(start, "", "unterminated string (a \" is missing before the end of the line)");
                    if (s[i] == '\\' && i + 1 < n) ++i;
                    text += s[i++];
                }
                if (i >= n) fail(start, "", "unterminated string");
                ++i;
                tokens_.push_back(Token{Token::Kind::string, text, 0.0, start});
                continue;
            }
            if (isPunctuation(c))
            {
                tokens_.push_back(Token{Token::Kind::punctuation, std::string(1, c), 0.0, line});
                ++i;
                continue;
            }
            if (c == '#' || c == '$')
            {
                std::size_t j = i;
                while (j < n && !std::isspace(static_cast<unsigned char>(s[j])) && !isPunctuation(s[j])) ++j;
                fail(line, "", "'" + s.substr(i, j - i) + "': directives and $macros are not supported in a scene; "
                     "write the value out");
            }
            if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126)
            {
                fail(line, "", "unexpected character (byte " + std::to_string(static_cast<unsigned char>(c))
                     + "); scene files are plain ASCII");
            }
            std::size_t j = i;
            while (j < n && !std::isspace(static_cast<unsigned char>(s[j])) && !isPunctuation(s[j]) && s[j] != '"'
                   && !(s[j] == '/' && j + 1 < n && (s[j + 1] == '/' || s[j + 1] == '*')))
            {
                const unsigned char u = static_cast<unsigned char>(s[j]);
                if (u < 32 || u > 126)
                {
                    fail(line, "", "unexpected character (byte " + std::to_string(u) + "); scene files are plain ASCII");
                }
                ++j;
            }
            Token t{Token::Kind::word, s.substr(i, j - i), 0.0, line};
            const char first = t.text[0];
            if (std::isdigit(static_cast<unsigned char>(first)) || first == '-' || first == '+' || first == '.')
            {
                errno = 0;
                char* end = nullptr;
                const double v = std::strtod(t.text.c_str(), &end);
                if (end && *end == '\0')
                {
                    // An overflow stays an infinite number, refused with its key where it is read.
                    t.kind = Token::Kind::number;
                    t.number = v;
                }
            }
            tokens_.push_back(t);
            i = j;
        }
        lastLine_ = line;
    }

    bool atEnd() const { return pos_ >= tokens_.size(); }
    const Token& peek() const { return tokens_[pos_]; }
    bool peekIs(const char* p) const
    {
        return !atEnd() && tokens_[pos_].kind == Token::Kind::punctuation && tokens_[pos_].text == p;
    }

    // Entries until '}' (closing) or the end of the file.
    void parseEntries(Dictionary& dict, bool closing, int openLine)
    {
        while (true)
        {
            if (atEnd())
            {
                if (closing)
                {
                    fail(openLine, dict.name_, "unbalanced braces: the '{' of this dictionary is never closed");
                }
                return;
            }
            const Token& t = peek();
            if (t.kind == Token::Kind::punctuation)
            {
                if (t.text == "}")
                {
                    if (!closing) fail(t.line, "", "unbalanced braces: '}' without a matching '{'");
                    ++pos_;
                    return;
                }
                if (t.text == ";") { ++pos_; continue; }   // stray ';' is harmless, as in OpenFOAM
                fail(t.line, "", "expected a key, got " + t.describe());
            }
            if (t.kind != Token::Kind::word)
            {
                fail(t.line, "", "expected a key, got " + t.describe());
            }
            Dictionary::Entry e;
            e.key = t.text;
            e.line = t.line;
            ++pos_;
            const std::string qkey = qualified(dict.name_, e.key);
            if (const Dictionary::Entry* prev = dict.lookup(e.key))
            {
                fail(e.line, qkey, "duplicate key (first given at line " + std::to_string(prev->line) + ")");
            }
            if (peekIs("{"))
            {
                const int open = peek().line;
                ++pos_;
                auto sub = std::make_shared<Dictionary>();
                sub->file_ = file_;
                sub->name_ = qkey;
                sub->line_ = e.line;
                parseEntries(*sub, true, open);
                e.dict = sub;
            }
            else
            {
                e.value = parseValueStream(qkey, e.line);
            }
            dict.entries_.push_back(std::move(e));
        }
    }

    // Values up to ';'. One value is the common case; several are kept as a list.
    Value parseValueStream(const std::string& qkey, int keyLine)
    {
        std::vector<Value> stream;
        // Optional dimension set [M L T ...], as in OpenFOAM's dimensioned entries.
        if (peekIs("["))
        {
            const int open = peek().line;
            ++pos_;
            while (!atEnd() && !peekIs("]"))
            {
                if (peek().kind != Token::Kind::number)
                {
                    fail(peek().line, qkey, "dimension set may hold only numbers, got " + peek().describe());
                }
                ++pos_;
            }
            if (atEnd()) fail(open, qkey, "unterminated dimension set '['");
            ++pos_;
        }
        while (true)
        {
            if (atEnd())
            {
                fail(keyLine, qkey, "missing ';' at the end of the entry");
            }
            const Token& t = peek();
            if (t.kind == Token::Kind::punctuation)
            {
                if (t.text == ";") { ++pos_; break; }
                if (t.text == "(") { stream.push_back(parseList(qkey)); continue; }
                if (t.text == "}" || t.text == "{")
                {
                    fail(keyLine, qkey, "missing ';' at the end of the entry (found '" + t.text + "' at line "
                         + std::to_string(t.line) + ")");
                }
                fail(t.line, qkey, "unexpected " + t.describe());
            }
            // A word on a later line than the key after at least one value is
            // almost always the next key of an entry that lost its ';'.
            if (!stream.empty() && t.line > keyLine && t.kind == Token::Kind::word)
            {
                fail(keyLine, qkey, "missing ';' at the end of the entry");
            }
            Value v;
            v.token = t;
            v.line = t.line;
            stream.push_back(v);
            ++pos_;
        }
        if (stream.empty())
        {
            fail(keyLine, qkey, "no value given");
        }
        if (stream.size() == 1) return stream.front();
        Value v;
        v.isList = false;
        v.items = std::move(stream);
        v.line = keyLine;
        v.token = Token{Token::Kind::punctuation, "<several>", 0.0, keyLine};
        return v;
    }

    Value parseList(const std::string& qkey)
    {
        Value list;
        list.isList = true;
        list.line = peek().line;
        const int open = list.line;
        ++pos_;
        while (true)
        {
            if (atEnd()) fail(open, qkey, "unterminated list: the '(' is never closed");
            const Token& t = peek();
            if (t.kind == Token::Kind::punctuation)
            {
                if (t.text == ")") { ++pos_; break; }
                if (t.text == "(") { list.items.push_back(parseList(qkey)); continue; }
                fail(t.line, qkey, "unexpected " + t.describe() + " inside a list (a ')' may be missing)");
            }
            Value v;
            v.token = t;
            v.line = t.line;
            list.items.push_back(v);
            ++pos_;
        }
        return list;
    }
};


// ---------------------------------------------------------------------------
Dictionary Dictionary::readFile(const std::string& path)
{
    std::ifstream is(path, std::ios::binary);
    if (!is)
    {
        throw InputError(path, 0, "", "cannot open file");
    }
    std::ostringstream os;
    os << is.rdbuf();
    const std::string text = os.str();
    if (text.size() > 16u*1024u*1024u)
    {
        throw InputError(path, 0, "", "file is larger than 16 MiB; a scene dictionary is a few kB");
    }
    return parse(text, path);
}

FloatingPointTrapsOff::FloatingPointTrapsOff()
{
    std::feholdexcept(&saved_);
}

FloatingPointTrapsOff::~FloatingPointTrapsOff()
{
    std::feclearexcept(FE_ALL_EXCEPT);
    std::fesetenv(&saved_);
}

Dictionary Dictionary::parse(const std::string& text, const std::string& fileName)
{
    const FloatingPointTrapsOff noTraps;
    DictionaryParser p(text, fileName);
    return p.parseTop();
}

const Dictionary::Entry* Dictionary::lookup(const std::string& key) const
{
    for (const Entry& e : entries_)
    {
        if (e.key == key) return &e;
    }
    return nullptr;
}

bool Dictionary::found(const std::string& key) const
{
    return lookup(key) != nullptr;
}

int Dictionary::lineOf(const std::string& key) const
{
    const Entry* e = lookup(key);
    return e ? e->line : line_;
}

bool Dictionary::isDict(const std::string& key) const
{
    const Entry* e = lookup(key);
    return e && e->dict;
}

void Dictionary::fail(const std::string& key, const std::string& message) const
{
    const Entry* e = key.empty() ? nullptr : lookup(key);
    throw InputError(file_, e ? e->line : line_, key.empty() ? name_ : qualified(name_, key), message);
}

const Dictionary::Entry& Dictionary::entry(const std::string& key) const
{
    const Entry* e = lookup(key);
    if (!e)
    {
        std::string where = name_.empty() ? "at the top level" : "in dictionary '" + name_ + "' (opened at line "
            + std::to_string(line_) + ")";
        throw InputError(file_, line_, qualified(name_, key), "missing key " + where);
    }
    return *e;
}

const Dictionary& Dictionary::subDict(const std::string& key) const
{
    const Entry& e = entry(key);
    if (!e.dict)
    {
        fail(key, "expected a dictionary { ... }, got " + e.value.describe());
    }
    return *e.dict;
}

const Token& Dictionary::singleToken(const std::string& key) const
{
    const Entry& e = entry(key);
    if (e.dict) fail(key, "expected a single value, got a dictionary { ... }");
    if (e.value.isList) fail(key, "expected a single value, got " + e.value.describe());
    if (!e.value.items.empty())
    {
        fail(key, "expected a single value, got " + std::to_string(e.value.items.size()) + " values");
    }
    return e.value.token;
}

double Dictionary::getScalar(const std::string& key) const
{
    const Token& t = singleToken(key);
    if (t.kind != Token::Kind::number) fail(key, "expected a number, got " + t.describe());
    if (!std::isfinite(t.number))
    {
        fail(key, "expected a finite number, got " + t.text + (std::isinf(t.number) ? " (beyond a double's range)" : ""));
    }
    return t.number;
}

double Dictionary::getScalar(const std::string& key, double deflt) const
{
    return found(key) ? getScalar(key) : deflt;
}

double Dictionary::getScalarInRange(const std::string& key, double lo, double hi,
                                    bool loInclusive, bool hiInclusive, const std::string& what) const
{
    const double v = getScalar(key);
    const bool okLo = loInclusive ? v >= lo : v > lo;
    const bool okHi = hiInclusive ? v <= hi : v < hi;
    if (!okLo || !okHi)
    {
        std::ostringstream os;
        os << what << " must lie in " << (loInclusive ? '[' : '(') << lo << ", " << hi << (hiInclusive ? ']' : ')')
           << ", got " << singleToken(key).text;
        fail(key, os.str());
    }
    return v;
}

int Dictionary::getLabel(const std::string& key) const
{
    const double v = getScalar(key);
    if (v != std::floor(v) || std::fabs(v) > 2.0e9)
    {
        fail(key, "expected an integer, got " + singleToken(key).text);
    }
    return static_cast<int>(v);
}

int Dictionary::getLabel(const std::string& key, int deflt) const
{
    return found(key) ? getLabel(key) : deflt;
}

std::string Dictionary::getWord(const std::string& key) const
{
    const Token& t = singleToken(key);
    if (t.kind != Token::Kind::word && t.kind != Token::Kind::string)
    {
        fail(key, "expected a word, got " + t.describe());
    }
    return t.text;
}

std::string Dictionary::getWord(const std::string& key, const std::string& deflt) const
{
    return found(key) ? getWord(key) : deflt;
}

std::string Dictionary::getWordOneOf(const std::string& key, const std::vector<std::string>& allowed) const
{
    const std::string w = getWord(key);
    if (std::find(allowed.begin(), allowed.end(), w) == allowed.end())
    {
        std::string list;
        for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
        fail(key, "'" + w + "' is not one of: " + list);
    }
    return w;
}

std::string Dictionary::getWordOneOf(const std::string& key, const std::vector<std::string>& allowed,
                                     const std::string& deflt) const
{
    return found(key) ? getWordOneOf(key, allowed) : deflt;
}

bool Dictionary::getBool(const std::string& key) const
{
    const Token& t = singleToken(key);
    const std::string& w = t.text;
    if (t.kind == Token::Kind::word)
    {
        if (w == "yes" || w == "on" || w == "true") return true;
        if (w == "no" || w == "off" || w == "false") return false;
    }
    fail(key, "expected yes/no (or on/off, true/false), got " + t.describe());
}

bool Dictionary::getBool(const std::string& key, bool deflt) const
{
    return found(key) ? getBool(key) : deflt;
}

std::vector<double> Dictionary::getScalarList(const std::string& key) const
{
    const Entry& e = entry(key);
    if (e.dict || !e.value.isList) fail(key, "expected a list ( ... ) of numbers");
    std::vector<double> out;
    for (const Value& v : e.value.items)
    {
        if (v.isList || v.token.kind != Token::Kind::number || !std::isfinite(v.token.number))
        {
            throw InputError(file_, v.line, qualified(name_, key), "expected a number in the list, got " + v.describe());
        }
        out.push_back(v.token.number);
    }
    return out;
}

std::vector<std::vector<double>> Dictionary::getTupleList(const std::string& key, std::size_t width) const
{
    const Entry& e = entry(key);
    if (e.dict || !e.value.isList)
    {
        fail(key, "expected a list of (" + std::to_string(width) + "-number) tuples, e.g. ((0 0) (10 -1))");
    }
    std::vector<std::vector<double>> out;
    for (const Value& v : e.value.items)
    {
        if (!v.isList || v.items.size() != width)
        {
            throw InputError(file_, v.line, qualified(name_, key), "expected a tuple of " + std::to_string(width)
                             + " numbers, got " + v.describe());
        }
        std::vector<double> row;
        for (const Value& x : v.items)
        {
            if (x.isList || x.token.kind != Token::Kind::number || !std::isfinite(x.token.number))
            {
                throw InputError(file_, x.line, qualified(name_, key), "expected a finite number, got " + x.describe());
            }
            row.push_back(x.token.number);
        }
        out.push_back(row);
    }
    return out;
}

void Dictionary::checkKnownKeys(const std::vector<std::string>& known) const
{
    for (const Entry& e : entries_)
    {
        if (std::find(known.begin(), known.end(), e.key) != known.end()) continue;
        std::string hint;
        std::size_t best = 3;
        for (const std::string& k : known)
        {
            const std::size_t d = editDistance(e.key, k);
            if (d < best) { best = d; hint = k; }
        }
        std::string list;
        for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
        throw InputError(file_, e.line, qualified(name_, e.key), "unknown key"
                         + (hint.empty() ? std::string() : " (did you mean '" + hint + "'?)")
                         + "; known keys here: " + list);
    }
}

} // namespace scene
} // namespace slide
