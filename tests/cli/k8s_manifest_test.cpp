// The Kubernetes manifests of scripts/k8s/, checked for structure (no cluster runs here, and
// Debian's kubectl predates Indexed Jobs): the grid is an Indexed Job whose pods take their
// shard with `--shard auto` from JOB_COMPLETION_INDEX and ANTIPODE_SHARD_COUNT, the count
// equals the Job's completions, and the merge reads the reports from the volume the grid
// writes them to.
#include <string>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

namespace {

YAML::Node manifest(const std::string& name) {
  return YAML::LoadFile(std::string(ANTIPODE_TEST_SOURCE_DIR) + "/scripts/k8s/" + name);
}

// The pod spec's one container.
YAML::Node container(const YAML::Node& job) {
  const YAML::Node containers = job["spec"]["template"]["spec"]["containers"];
  EXPECT_EQ(containers.size(), 1u);
  return containers[0];
}

std::string command_line(const YAML::Node& c) {
  std::string text;
  for (const auto& part : c["command"]) text += part.as<std::string>() + " ";
  for (const auto& part : c["args"]) text += part.as<std::string>() + " ";
  return text;
}

TEST(K8sManifests, TheGridIsAnIndexedJobWhosePodsTakeTheirShardFromTheirIndex) {
  const YAML::Node grid = manifest("bench-indexed-job.yaml");
  EXPECT_EQ(grid["apiVersion"].as<std::string>(), "batch/v1");
  EXPECT_EQ(grid["kind"].as<std::string>(), "Job");
  EXPECT_EQ(grid["spec"]["completionMode"].as<std::string>(), "Indexed");
  EXPECT_EQ(grid["spec"]["template"]["spec"]["restartPolicy"].as<std::string>(), "Never");
  const int completions = grid["spec"]["completions"].as<int>();
  const YAML::Node shard = container(grid);
  std::string count;
  for (const auto& variable : shard["env"])
    if (variable["name"].as<std::string>() == "ANTIPODE_SHARD_COUNT")
      count = variable["value"].as<std::string>();
  EXPECT_EQ(count, std::to_string(completions)) << "ANTIPODE_SHARD_COUNT must equal completions";
  const std::string line = command_line(shard);
  EXPECT_NE(line.find("antipode bench "), std::string::npos) << line;
  EXPECT_NE(line.find("--shard auto"), std::string::npos) << line;
  EXPECT_NE(line.find("--report /results/shard-$JOB_COMPLETION_INDEX.json"), std::string::npos)
      << line;
}

TEST(K8sManifests, TheMergeReadsTheShardsFromTheVolumeTheGridWritesThemTo) {
  const YAML::Node grid = manifest("bench-indexed-job.yaml");
  const YAML::Node merge = manifest("bench-merge-job.yaml");
  EXPECT_EQ(merge["kind"].as<std::string>(), "Job");
  const std::string line = command_line(container(merge));
  EXPECT_NE(line.find("antipode bench merge /results/shard-*.json --report /results/"),
            std::string::npos)
      << line;
  const auto claim = [](const YAML::Node& job) {
    return job["spec"]["template"]["spec"]["volumes"][0]["persistentVolumeClaim"]["claimName"]
        .as<std::string>();
  };
  EXPECT_EQ(claim(merge), claim(grid));
  const auto mount = [&](const YAML::Node& job) {
    return container(job)["volumeMounts"][0]["mountPath"].as<std::string>();
  };
  EXPECT_EQ(mount(merge), "/results");
  EXPECT_EQ(mount(grid), "/results");
}

}  // namespace
