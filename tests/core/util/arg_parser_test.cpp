#include "util/arg_parser.h"

#include <gtest/gtest.h>

namespace grass {
namespace {

struct Parsed {
    int width = 1280;
    std::string out, project, geometry = "auto";
    bool json = false;
    std::uint64_t seed = 1;
};

ArgParser makeParser(Parsed& p) {
    ArgParser parser("test <project>", "A test command.");
    parser.positional("project", "the project", &p.project, true);
    parser.integer("--width", "width", &p.width, 1, 16384);
    parser.text("--out", "FILE", "output", &p.out);
    parser.flag("--json", "json", &p.json);
    parser.unsignedInteger("--seed", "seed", &p.seed);
    parser.choice("--geometry", {"auto", "tess", "strips"}, "path", &p.geometry);
    return parser;
}

TEST(ArgParser, ParsesOptionsInBothSpellings) {
    Parsed p;
    ArgParser parser = makeParser(p);
    ASSERT_TRUE(parser
                    .parse({"meadow", "--width", "640", "--out=x.png", "--json", "--seed", "42",
                            "--geometry", "tess"})
                    .ok());
    EXPECT_EQ(p.project, "meadow");
    EXPECT_EQ(p.width, 640);
    EXPECT_EQ(p.out, "x.png");
    EXPECT_TRUE(p.json);
    EXPECT_EQ(p.seed, 42u);
    EXPECT_EQ(p.geometry, "tess");
    EXPECT_TRUE(parser.given("--width"));
    EXPECT_FALSE(parser.helpRequested());
}

TEST(ArgParser, BadIntegersNameTheOptionAndTheRange) {
    for (const char* bad : {"0", "abc", "-5", "16385", "12px", "", "99999999999999999999"}) {
        Parsed p;
        ArgParser parser = makeParser(p);
        auto result = parser.parse({"meadow", "--width", bad});
        ASSERT_FALSE(result.ok()) << bad;
        EXPECT_EQ(result.error().path, "--width");
        EXPECT_NE(result.error().message.find("1 to 16384"), std::string::npos)
            << result.error().message;
        EXPECT_EQ(p.width, 1280) << "a rejected value must not be stored";
    }
}

TEST(ArgParser, UnknownOptionMissingValueAndMissingPositionalAreErrors) {
    Parsed p;
    EXPECT_EQ(makeParser(p).parse({"meadow", "--nope"}).error().path, "--nope");
    EXPECT_EQ(makeParser(p).parse({"meadow", "--out"}).error().path, "--out");
    EXPECT_EQ(makeParser(p).parse({"--width", "5"}).error().path, "project");
    EXPECT_EQ(makeParser(p).parse({"meadow", "extra"}).error().path, "extra");
    EXPECT_EQ(makeParser(p).parse({"meadow", "--geometry", "quads"}).error().path, "--geometry");
    EXPECT_EQ(makeParser(p).parse({"meadow", "--json=yes"}).error().path, "--json");
    EXPECT_EQ(makeParser(p).parse({"meadow", "--seed", "-1"}).error().path, "--seed");
}

TEST(ArgParser, HelpListsEveryOption) {
    Parsed p;
    ArgParser parser = makeParser(p);
    ASSERT_TRUE(parser.parse({"--help"}).ok());
    EXPECT_TRUE(parser.helpRequested());
    const std::string help = parser.help();
    for (const char* name :
         {"--width", "--out", "--json", "--seed", "--geometry", "project", "--help"})
        EXPECT_NE(help.find(name), std::string::npos) << name;
}

}  // namespace
}  // namespace grass
