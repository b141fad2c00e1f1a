// Literal conversion: strict built-in parsing and plugin-added types.
#include "test_support.hpp"

namespace antipode::bt::testing {
namespace {

template <typename T>
std::optional<T> parse(const std::string& text) {
  const LiteralConverters table;
  auto value = table.parse_text(std::type_index(typeid(T)), text);
  if (!value) return std::nullopt;
  return std::any_cast<T>(*value);
}

TEST(ConvertersTest, NumbersAreParsedStrictly) {
  EXPECT_EQ(parse<int>("42"), 42);
  EXPECT_EQ(parse<int>("+5"), 5);
  EXPECT_EQ(parse<int>("-3"), -3);
  EXPECT_EQ(parse<int>("3.5"), std::nullopt);
  EXPECT_EQ(parse<int>("12abc"), std::nullopt);
  EXPECT_EQ(parse<int>("99999999999"), std::nullopt);
  EXPECT_EQ(parse<long>("99999999999"), 99999999999L);
  EXPECT_EQ(parse<unsigned long>("-1"), std::nullopt);
  EXPECT_EQ(parse<double>("2.5e-3"), 2.5e-3);
  EXPECT_EQ(parse<double>("x"), std::nullopt);
  EXPECT_EQ(parse<double>("nan"), std::nullopt);
  EXPECT_EQ(parse<double>("inf"), std::nullopt);
  EXPECT_EQ(parse<float>("-inf"), std::nullopt);
  EXPECT_EQ(parse<std::vector<double>>("[0, nan, 1]"), std::nullopt);
}

TEST(ConvertersTest, BoolsListsAndDurations) {
  EXPECT_EQ(parse<bool>("true"), true);
  EXPECT_EQ(parse<bool>("False"), false);
  EXPECT_EQ(parse<bool>("1"), std::nullopt);
  EXPECT_EQ(parse<std::vector<std::string>>("[left, right]"),
            (std::vector<std::string>{"left", "right"}));
  EXPECT_EQ(parse<std::vector<std::string>>("left"), std::nullopt);
  EXPECT_EQ(parse<std::vector<int>>("[1, 2]"), (std::vector<int>{1, 2}));
  EXPECT_EQ(parse<std::chrono::milliseconds>("9223372036854775807"), std::nullopt);
  EXPECT_EQ(parse<std::chrono::milliseconds>("250"), std::chrono::milliseconds(250));
  EXPECT_EQ(parse<std::chrono::milliseconds>("-1"), std::nullopt);
  EXPECT_EQ(parse<std::string>("[not, parsed]"), "[not, parsed]");
}

TEST(ConvertersTest, ValuesPrintForLogs) {
  const LiteralConverters table;
  EXPECT_EQ(table.format(std::any(std::vector<double>{0.5, 2})), "[0.5, 2]");
  EXPECT_EQ(table.format(std::any(true)), "true");
  EXPECT_EQ(table.format(std::any()), "<empty>");
  EXPECT_EQ(type_name<std::vector<std::string>>(), "list of string");
  EXPECT_EQ(type_name<std::shared_ptr<const Cloud>>(), "std::shared_ptr<antipode::Cloud const>");
}

struct Point {
  double x = 0;
  double y = 0;
};

class ReadPoint : public SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static NodeManifest manifest() {
    NodeManifest made;
    made.type = "ReadPoint";
    made.ports = {input_port<Point>("at", "a point")};
    return made;
  }

 protected:
  Status tick() override {
    const Point at = get_input<Point>("at");
    log(expand({"{where}"}));
    return at.x == 1 && at.y == 2 ? Status::kSuccess : Status::kFailure;
  }
};

using PluginTypeTest = TreeTest;

TEST_F(PluginTypeTest, APluginTypeAcceptsLiteralsOnceItHasAConverter) {
  registry.register_node<ReadPoint>();
  const std::string yaml = "main: t\ntrees:\n  t:\n    ReadPoint: { at: [1, 2] }\n";
  EXPECT_NE(validation_error(yaml), "");
  registry.converters().add<Point>(
      [](const YAML::Node& value) {
        if (!value.IsSequence() || value.size() != 2) throw std::invalid_argument("not x, y");
        return Point{value[0].as<double>(), value[1].as<double>()};
      },
      [](const Point& p) { return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")"; });
  Tree tree = load(yaml);
  tree.blackboard().set("where", Point{3, 4});
  EXPECT_EQ(tree.tick_once(), Status::kSuccess);
  EXPECT_EQ(log, std::vector<std::string>{"(3.000000, 4.000000)"});
  // Text entries (here from --set) convert through the same table.
  options.overrides = {{"p", "[1, 2]"}};
  Tree from_text = load("main: t\ntrees:\n  t:\n    ReadPoint: { at: \"{p}\" }\n");
  EXPECT_EQ(from_text.tick_once(), Status::kSuccess);
  options.overrides = {{"p", "[1, 2, 3]"}};
  EXPECT_NE(validation_error("main: t\ntrees:\n  t:\n    ReadPoint: { at: \"{p}\" }\n"), "");
  options.overrides.clear();
  EXPECT_EQ(validation_error("main: t\ntrees:\n  t:\n    ReadPoint: { at: [1] }\n"),
            "trees/t.yaml:4:22: port 'at' of ReadPoint expects "
            "antipode::bt::testing::(anonymous namespace)::Point, got a list");
}

}  // namespace
}  // namespace antipode::bt::testing
