#include "bench_shard.hpp"

#include <charconv>

#include "antipode/core/error.hpp"

namespace antipode::cli {
namespace {

// The whole of `text` as a number in [1, 10000], or 0.
int shard_number(const std::string& text) {
  int value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  return error == std::errc() && stop == end && value >= 1 && value <= 10000 ? value : 0;
}

}  // namespace

std::string BenchShard::str() const {
  return "shard " + std::to_string(index) + "/" + std::to_string(count);
}

BenchShard parse_shard(const std::string& text) {
  if (text.empty()) return {};
  const std::size_t slash = text.find('/');
  const int index = slash == std::string::npos ? 0 : shard_number(text.substr(0, slash));
  const int count = slash == std::string::npos ? 0 : shard_number(text.substr(slash + 1));
  if (index == 0 || count == 0 || index > count)
    throw Error("--shard: '" + text + "' is not i/n with 1 <= i <= n <= 10000 (e.g. --shard 2/4)");
  return {index, count};
}

std::vector<std::size_t> shard_tasks(std::size_t total, const BenchShard& shard) {
  std::vector<std::size_t> tasks;
  for (std::size_t i = std::size_t(shard.index - 1); i < total; i += std::size_t(shard.count))
    tasks.push_back(i);
  return tasks;
}

nlohmann::ordered_json shard_json(const BenchShard& shard, std::size_t total) {
  return {{"index", shard.index}, {"count", shard.count}, {"tasks", total}};
}

void require_shard_report(const BenchShard& shard, const std::string& report_path) {
  if (!shard.whole() && report_path.empty())
    throw Error("--shard " + std::to_string(shard.index) + "/" + std::to_string(shard.count) +
                " needs --report: a shard's records are merged from its report "
                "(antipode bench merge)");
}

}  // namespace antipode::cli
