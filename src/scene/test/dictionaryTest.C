// The OpenFOAM-syntax reader: what it accepts and how it reports what it does not.
#include "dictionary.H"

#include <gtest/gtest.h>

using slide::scene::Dictionary;
using slide::scene::InputError;

namespace
{

// Runs f, expects an InputError, returns it.
template<class F>
InputError expectError(F f)
{
    try
    {
        f();
    }
    catch (const InputError& e)
    {
        return e;
    }
    ADD_FAILURE() << "no InputError thrown";
    return InputError("", 0, "", "");
}

} // namespace

TEST(Dictionary, ParsesOpenFOAMSyntax)
{
    const std::string text = R"(FoamFile
{
    version 2.0;  format ascii;
    class dictionary;  object sceneProperties;
}
// a comment
g 9.81;   /* block
comment */
rho [1 -3 0 0 0 0 0] 600;
name "Krone & Wright";
flag yes;
base
{
    profile polyline;
    points ((0 0) (10 -1.5) (20.5 -2));
}
list (1 2.5 -3e-2);
)";
    const Dictionary d = Dictionary::parse(text, "mem");
    EXPECT_DOUBLE_EQ(d.getScalar("g"), 9.81);
    EXPECT_DOUBLE_EQ(d.getScalar("rho"), 600.0);
    EXPECT_EQ(d.getWord("name"), "Krone & Wright");
    EXPECT_TRUE(d.getBool("flag"));
    const Dictionary& b = d.subDict("base");
    EXPECT_EQ(b.getWord("profile"), "polyline");
    const auto pts = b.getTupleList("points", 2);
    ASSERT_EQ(pts.size(), 3u);
    EXPECT_DOUBLE_EQ(pts[2][0], 20.5);
    EXPECT_DOUBLE_EQ(pts[1][1], -1.5);
    EXPECT_EQ(b.line(), 12);
    EXPECT_EQ(b.entry("points").line, 15);
    const auto l = d.getScalarList("list");
    ASSERT_EQ(l.size(), 3u);
    EXPECT_DOUBLE_EQ(l[2], -0.03);
    EXPECT_DOUBLE_EQ(d.getScalar("missing", 4.0), 4.0);
}

TEST(Dictionary, MissingKeyNamesFileLineAndKey)
{
    const Dictionary d = Dictionary::parse("a 1;\nsub\n{\n    b 2;\n}\n", "case/constant/sceneProperties");
    const InputError e = expectError([&] { d.subDict("sub").getScalar("c"); });
    EXPECT_EQ(e.file(), "case/constant/sceneProperties");
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.key(), "sub.c");
    EXPECT_NE(std::string(e.what()).find("case/constant/sceneProperties:2: key 'sub.c': missing key"),
              std::string::npos) << e.what();
}

TEST(Dictionary, WrongTypeNamesTheLine)
{
    const Dictionary d = Dictionary::parse("a 1;\n\nb abc;\nc (1 2);\nd { }\n", "f");
    InputError e = expectError([&] { d.getScalar("b"); });
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.key(), "b");
    EXPECT_NE(e.message().find("expected a number, got word 'abc'"), std::string::npos);
    e = expectError([&] { d.getScalar("c"); });
    EXPECT_EQ(e.line(), 4);
    e = expectError([&] { d.getScalar("d"); });
    EXPECT_EQ(e.line(), 5);
    e = expectError([&] { d.subDict("a"); });
    EXPECT_EQ(e.line(), 1);
    e = expectError([&] { d.getBool("a"); });
    EXPECT_EQ(e.key(), "a");
}

TEST(Dictionary, SyntaxErrorsAreReportedWithLines)
{
    struct Case { const char* text; int line; const char* fragment; };
    const Case cases[] = {
        {"a 1;\nsub\n{\n  b 2;\n", 3, "never closed"},
        {"a 1;\n}\n", 2, "without a matching"},
        {"a 1\nb 2;\n", 1, "missing ';'"},
        {"a 1;\nsub { b 2 }\n", 2, "missing ';'"},
        {"a (1 2;\n", 1, "unexpected ';'"},
        {"a \"open;\n", 1, "unterminated string"},
        {"/* open\n\n a 1;", 1, "unterminated /* comment"},
        {"a 1;\n#include \"x\"\n", 2, "not supported"},
        {"a $b;\n", 1, "not supported"},
        {"a 1;\na 2;\n", 2, "duplicate key"},
        {"a;\n", 1, "no value"},
        {"(1 2);\n", 1, "expected a key"},
        {"a [1 x] 2;\n", 1, "dimension set"},
        {"a \x01;\n", 1, "unexpected character"},
    };
    for (const Case& c : cases)
    {
        const InputError e = expectError([&] { Dictionary::parse(c.text, "f"); });
        EXPECT_EQ(e.line(), c.line) << c.text;
        EXPECT_NE(e.message().find(c.fragment), std::string::npos) << c.text << " -> " << e.what();
    }
}

TEST(Dictionary, NonFiniteNumbersAreRejected)
{
    // 1e999 overflows a double: refused where it is read, naming its key.
    const Dictionary d = Dictionary::parse("a nan;\nb inf;\nc -inf;\nd 1e999;\n", "f");
    for (const char* k : {"a", "b", "c", "d"})
    {
        const InputError e = expectError([&] { d.getScalar(k); });
        EXPECT_EQ(e.key(), k);
    }
}

TEST(Dictionary, UnknownKeysSuggestTheIntendedOne)
{
    const Dictionary d = Dictionary::parse("s_uo 1;\ndelta_rem 0.5;\n", "f");
    const InputError e = expectError([&] { d.checkKnownKeys({"s_uo", "deltaRem", "xi95"}); });
    EXPECT_EQ(e.key(), "delta_rem");
    EXPECT_EQ(e.line(), 2);
    EXPECT_NE(e.message().find("did you mean 'deltaRem'"), std::string::npos) << e.what();
}

TEST(Dictionary, RangesAndLabels)
{
    const Dictionary d = Dictionary::parse("a 0;\nb 2.5;\nc 7;\n", "f");
    EXPECT_THROW(d.getScalarInRange("a", 0.0, 1.0, false, true, "x"), InputError);
    EXPECT_DOUBLE_EQ(d.getScalarInRange("a", 0.0, 1.0, true, true, "x"), 0.0);
    EXPECT_THROW(d.getLabel("b"), InputError);
    EXPECT_EQ(d.getLabel("c"), 7);
    EXPECT_THROW(d.getWordOneOf("c", {"x", "y"}), InputError);
}

TEST(Dictionary, MissingFileIsAnInputError)
{
    const InputError e = expectError([&] { Dictionary::readFile("/nonexistent/constant/sceneProperties"); });
    EXPECT_EQ(e.file(), "/nonexistent/constant/sceneProperties");
    EXPECT_NE(e.message().find("cannot open"), std::string::npos);
}
