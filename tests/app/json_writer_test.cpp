// The JSON writer of the command line, in-process: what it writes parses strictly and reads back.
#include "cli/json_writer.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "cli_test_support.h"

namespace somicage {
namespace {

using namespace somicage::test;

TEST(CliJsonWriter, WritesWhatAStrictParserReadsBack) {
  std::ostringstream out;
  {
    JsonObjectWriter json(out);
    json.field("text", std::string("quote \" backslash \\ newline \n tab \t bell \x07"));
    json.field("pointer", "plain");
    json.field("third", 1.0 / 3.0);
    json.field("nan", std::nan(""));
    json.field("inf", std::numeric_limits<double>::infinity());
    json.field("int", -7);
    json.field("big", 1LL << 40);
    json.field("yes", true);
    json.null("nothing");
    json.field("empty", std::vector<std::string>{});
    json.field("list", std::vector<std::string>{"a", "b"});
    json.field("timings", std::vector<std::pair<std::string, double>>{{"cpu", 1.5}, {"gpu", std::nan("")}});
  }  // the destructor closes the object
  const Json json = JsonParser::parse(out.str());
  EXPECT_EQ(json["text"].string, "quote \" backslash \\ newline \n tab \t bell \x07");
  EXPECT_EQ(json["pointer"].string, "plain");
  EXPECT_EQ(json["third"].number, 1.0 / 3.0) << "shortest round-trip text";
  EXPECT_EQ(json["nan"].type, Json::Type::Null);
  EXPECT_EQ(json["inf"].type, Json::Type::Null);
  EXPECT_EQ(json["int"].number, -7);
  EXPECT_EQ(json["big"].number, 1099511627776.0);
  EXPECT_TRUE(json["yes"].boolean);
  EXPECT_EQ(json["nothing"].type, Json::Type::Null);
  EXPECT_TRUE(json["empty"].array.empty());
  ASSERT_EQ(json["list"].array.size(), 2u);
  EXPECT_EQ(json["list"].array[1].string, "b");
  EXPECT_EQ(json["timings"]["cpu"].number, 1.5);
  EXPECT_EQ(json["timings"]["gpu"].type, Json::Type::Null);
}

TEST(CliJsonWriter, EmptyObject) {
  std::ostringstream out;
  JsonObjectWriter(out).close();
  EXPECT_EQ(JsonParser::parse(out.str()).type, Json::Type::Object);
}

}  // namespace
}  // namespace somicage
