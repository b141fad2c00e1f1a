#include "antipode/core/parameters.hpp"

#include <gtest/gtest.h>

namespace antipode {
namespace {

Parameters parse(const std::string& text) {
  return Parameters(YAML::Load(text), "component 'sampler'", "trees/t.yaml");
}

TEST(ParametersTest, ReadsTypedValuesWithFallbacks) {
  const Parameters params = parse("samples: 400\nvoxel_size_m: 0.004\nname: x");
  EXPECT_EQ(params.get<int>("samples", 1), 400);
  EXPECT_DOUBLE_EQ(params.get<double>("voxel_size_m", 0.003), 0.004);
  EXPECT_EQ(params.get<int>("threads", 2), 2);
  EXPECT_EQ(params.require<std::string>("name"), "x");
  EXPECT_NO_THROW(params.reject_unknown());
}

TEST(ParametersTest, UnknownKeyIsLocatedAndSuggested) {
  const Parameters params = parse("samples: 1\nsampels: 2");
  params.get<int>("samples", 0);
  try {
    params.reject_unknown();
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_STREQ(error.what(),
                 "trees/t.yaml:2:1: unknown parameter 'sampels' of component 'sampler' "
                 "(did you mean 'samples'?)");
  }
}

// Found by fuzzing scene files: a key that is a list or a mapping is an error, not a crash.
TEST(ParametersTest, AKeyThatIsNotANameIsALocatedError) {
  const Parameters params = parse("samples: 1\n[a, b]: 2");
  params.get<int>("samples", 0);
  try {
    params.reject_unknown();
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_STREQ(error.what(),
                 "trees/t.yaml:2:1: a parameter of component 'sampler' is named by a list or a "
                 "mapping, not a name");
  }
}

TEST(ParametersTest, BadTypeAndMissingKeyAreClearErrors) {
  const Parameters params = parse("samples: many");
  try {
    params.get<int>("samples", 0);
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_STREQ(error.what(),
                 "trees/t.yaml:1:1: parameter 'samples' of component 'sampler' must be an "
                 "integer, got 'many'");
  }
  EXPECT_THROW(params.require<double>("radius_m"), Error);
}

TEST(ParametersTest, NonMappingIsRejected) { EXPECT_THROW(parse("[1, 2]"), Error); }

}  // namespace
}  // namespace antipode
