#pragma once
/// @file
/// antipode's binary container for large numeric files (training sets, classifier models):
///
///   magic (8 bytes) | format version (uint32) | payload size (uint64) | FNV-1a 64 of the
///   payload (uint64) | payload
///
/// all little-endian, as written by this machine (x86-64 and arm64 both are). The checksum
/// turns a truncated or corrupted file into a clear error instead of garbage numbers. Written
/// by hand because the container is a few lines and the Debian serialisation libraries either
/// store floats one by one (JSON, CBOR: tens of megabytes of tags for a model) or bring a
/// schema compiler (protobuf, flatbuffers).

#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "antipode/core/error.hpp"

namespace antipode {

/// Builds a payload in memory; write() puts it in a file atomically.
class BinaryWriter {
 public:
  /// `magic` is exactly 8 characters (e.g. "ANTPSVM1"); `version` the payload's layout.
  BinaryWriter(std::string magic, std::uint32_t version);

  template <typename T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>, "put() copies bytes");
    append(&value, sizeof(T));
  }
  void put_string(const std::string& text);
  /// The element count (uint64), then the elements.
  template <typename T>
  void put_vector(const std::vector<T>& values) {
    static_assert(std::is_trivially_copyable_v<T>, "put_vector() copies bytes");
    put<std::uint64_t>(values.size());
    append(values.data(), values.size() * sizeof(T));
  }

  /// Writes header and payload to `path` all-or-nothing (write_file_atomically); an
  /// antipode::Error naming `path` when it cannot.
  void write(const std::string& path) const;

 private:
  void append(const void* data, std::size_t bytes);
  std::string magic_;
  std::uint32_t version_;
  std::vector<char> payload_;
};

/// Checks that `path` is a whole, uncorrupted file written by BinaryWriter - any antipode
/// magic, its payload size and checksum - without decoding the payload, so that a command can
/// refuse a damaged input before the work that precedes reading it. Throws the errors
/// BinaryReader would, naming the file and `what` it was meant to be ("classifier model").
void check_binary_file(const std::string& path, const std::string& what);

/// Reads a whole file written by BinaryWriter and checks its header and checksum; get*()
/// then read the payload in order. Every failure is an antipode::Error naming the file and
/// `what` it was meant to be ("classifier model", ...).
class BinaryReader {
 public:
  /// Accepts format versions 1..`newest_version`.
  BinaryReader(const std::string& path, const std::string& magic, std::uint32_t newest_version,
               std::string what);

  std::uint32_t version() const { return version_; }
  const std::string& path() const { return path_; }

  template <typename T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>, "get() copies bytes");
    T value;
    take(&value, sizeof(T));
    return value;
  }
  std::string get_string();
  template <typename T>
  std::vector<T> get_vector() {
    static_assert(std::is_trivially_copyable_v<T>, "get_vector() copies bytes");
    const auto count = get<std::uint64_t>();
    if (count > remaining() / sizeof(T)) fail("a length runs past the end of the file");
    std::vector<T> values(static_cast<std::size_t>(count));
    take(values.data(), values.size() * sizeof(T));
    return values;
  }
  /// Fails unless the whole payload has been read.
  void expect_end() const;
  /// Throws antipode::Error "<path>: <what> file: <message>".
  [[noreturn]] void fail(const std::string& message) const;

 private:
  std::size_t remaining() const { return payload_.size() - offset_; }
  void take(void* data, std::size_t bytes);
  std::string path_;
  std::string what_;
  std::uint32_t version_ = 0;
  std::vector<char> payload_;
  std::size_t offset_ = 0;
};

}  // namespace antipode
