// format_json: both layouts parse back to the same document; the pretty layout keeps
// values that fit on one line and fills lines with points (issue 23: a floor plan was
// written one number per line, 1,744 lines).
#include <gtest/gtest.h>
#include <preimage/scene/import.hpp>
#include <preimage/scene/scene.hpp>

#include <algorithm>
#include <random>
#include <sstream>

using namespace preimage;
using nlohmann::json;

namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

json random_document(std::mt19937& rng, int depth) {
  std::uniform_int_distribution<int> kind(0, depth > 0 ? 6 : 3);
  switch (kind(rng)) {
    case 0: return std::uniform_real_distribution<double>(-1e6, 1e6)(rng);
    case 1: return static_cast<int>(rng() % 1000);
    case 2: {
      const auto letter = static_cast<char>('a' + rng() % 26);  // drawn first: the order g++ gave the arguments
      return std::string(rng() % 40, letter);
    }
    case 3: return rng() % 2 == 0 ? json(nullptr) : json(true);
    case 4: {
      json a = json::array();
      for (unsigned i = 0, n = rng() % 30; i < n; ++i) a.push_back(json::array({double(rng() % 100) / 8, double(rng() % 100) / 8}));
      return a;
    }
    case 5: {
      json a = json::array();
      for (unsigned i = 0, n = rng() % 6; i < n; ++i) a.push_back(random_document(rng, depth - 1));
      return a;
    }
    default: {
      json o = json::object();
      for (unsigned i = 0, n = rng() % 6; i < n; ++i) {
        std::string key(1 + rng() % 20, 'x');
        key += std::to_string(i);
        o[key] = random_document(rng, depth - 1);
      }
      return o;
    }
  }
}

}  // namespace

TEST(JsonLayout, BothLayoutsRoundTripAndPrettyLinesStayWithinTheWidth) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 500; ++trial) {
    const json doc = random_document(rng, 4);
    const std::string compact = scene::format_json(doc, scene::JsonLayout::Compact);
    const std::string pretty = scene::format_json(doc, scene::JsonLayout::Pretty, 60);
    ASSERT_EQ(json::parse(compact), doc) << compact;
    ASSERT_EQ(json::parse(pretty), doc) << pretty;
    EXPECT_EQ(compact.find('\n'), std::string::npos);
    for (const auto& line : lines_of(pretty)) {
      // A line (its separating comma aside) may pass the width only when what it holds
      // cannot be broken: a scalar (after its key), or the opening of an expanded object
      // or array.
      std::string body = line;
      if (body.back() == ',') body.pop_back();
      if (body.size() <= 60) continue;
      if (body.back() == '[' || body.back() == '{') body.pop_back();
      EXPECT_EQ(body.find_first_of("[{"), std::string::npos) << "line of " << line.size() << " columns: " << line;
    }
  }
}

TEST(JsonLayout, AFloorPlanIsAFewLinesPerRingNotOneNumberPerLine) {
  const auto s = scene::import_houseexpo(std::string(PREIMAGE_FLOORPLANS) + "/house_expo_room_1451.json");
  const json doc = scene::to_json(s);
  std::size_t numbers = 0;
  for (const auto& v : doc["environment"]["boundary"]) numbers += v.size();
  const auto lines = lines_of(scene::format_json(doc, scene::JsonLayout::Pretty));
  EXPECT_LT(lines.size() * 4, numbers) << "pretty output has " << lines.size() << " lines";
  // Only a long string (the description) may pass the width; lines of points do not.
  EXPECT_TRUE(std::all_of(lines.begin(), lines.end(), [](const std::string& l) { return l.size() <= 100 || l.find('[') == std::string::npos; }));
}
