#pragma once
// The pipeline nodes' JSON files: written whole or not at all.

#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "antipode/core/atomic_file.hpp"
#include "antipode/core/error.hpp"

namespace antipode::pipeline {

/// Writes `document` (indented by one space, a newline at the end) to `file` through
/// write_file_atomically(): a failed write leaves no file and throws antipode::Error naming it.
template <class Json>
void write_json_file(const std::string& file, const Json& document) {
  write_file_atomically(file, [&](const std::string& temporary) {
    std::ofstream out(temporary);
    out << document.dump(1) << "\n";
    out.close();  // flushes: a failure to write the last bytes shows here
    if (!out) throw Error("write failed");
  });
}

}  // namespace antipode::pipeline
