// core/base/json.h: the one encoding of numbers and strings that sessions and every command's --json use. A number
// reads back to the same double from the shortest text; a non-finite one is null (sessions wrote 0 before, silently,
// while
// --json wrote null); strings escape what JSON requires.
#include "base/json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "base/errors.h"

namespace somicage {
namespace {

TEST(Json, NumbersReadBackBitwiseFromTheShortestText) {
  const double values[] = {0.1, 1.0 / 3.0, -2.5e-310, 9007199254740993.0, 1e300, -0.0, 0.45};
  for (const double x : values) {
    std::string text;
    appendJsonNumber(x, text);
    const double back = parseJson(text, "number").asNumber();
    EXPECT_EQ(std::memcmp(&back, &x, sizeof x), 0) << text;
    EXPECT_LE(text.size(), 24u) << text;  // at most 17 significant digits, a sign, a point and an exponent
  }
  std::string tenth;
  appendJsonNumber(0.1, tenth);
  EXPECT_EQ(tenth, "0.1") << "the shortest text, not %.17g's 0.10000000000000001";
}

TEST(Json, NonFiniteNumbersAreNullInEveryWriter) {
  JsonValue row = JsonValue::array();
  row.push(JsonValue::number(std::numeric_limits<double>::quiet_NaN()));
  row.push(JsonValue::number(std::numeric_limits<double>::infinity()));
  row.push(JsonValue::number(1.5));
  EXPECT_EQ(row.dump(), "[null, null, 1.5]\n");
  std::string text;
  appendJsonNumber(-std::numeric_limits<double>::infinity(), text);
  EXPECT_EQ(text, "null");
  // null reads back as null, never as a number: a session holding one is refused where it needs a number.
  EXPECT_TRUE(parseJson(row.dump(), "row").items()[0].isNull());
}

TEST(Json, StringsEscapeQuotesBackslashesAndControlCharacters) {
  std::string text;
  appendJsonString(std::string("a\"b\\c\nd\x01", 8), text);
  EXPECT_EQ(text, "\"a\\\"b\\\\c\\nd\\u0001\"");
  EXPECT_EQ(parseJson(text, "string").asString(), std::string("a\"b\\c\nd\x01", 8));
}

}  // namespace
}  // namespace somicage
