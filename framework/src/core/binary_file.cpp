#include "antipode/core/binary_file.hpp"

#include <algorithm>
#include <fstream>

#include "antipode/core/atomic_file.hpp"
#include "antipode/core/input_file.hpp"

namespace antipode {
namespace {

constexpr std::size_t kMagicSize = 8;
constexpr std::size_t kHeaderSize = kMagicSize + sizeof(std::uint32_t) + 2 * sizeof(std::uint64_t);

std::uint64_t fnv1a(const std::vector<char>& bytes) {
  std::uint64_t hash = 14695981039346656037ULL;
  for (const char c : bytes) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 1099511628211ULL;
  }
  return hash;
}

template <typename T>
T read_at(const std::vector<char>& bytes, std::size_t offset) {
  T value;
  std::memcpy(&value, bytes.data() + offset, sizeof(T));
  return value;
}

[[noreturn]] void fail_file(const std::string& path, const std::string& what,
                            const std::string& message) {
  throw Error(what + " file: " + message, SourceLocation{path});
}

struct Container {
  std::uint32_t version = 0;
  std::vector<char> payload;
};

// The version and checked payload of the file `path`, whose magic must be `magic`, or any
// antipode magic ("ANTP...") when `magic` is empty.
Container read_container(const std::string& path, const std::string& what,
                         const std::string& magic) {
  require_regular_file(path, "a " + what + " file");
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw Error("cannot open " + what + " file", SourceLocation{path});
  // One read of the whole file, not a copy through stream iterators byte by byte.
  std::vector<char> bytes(static_cast<std::size_t>(std::max<std::streamoff>(0, in.tellg())));
  in.seekg(0);
  if (!in.read(bytes.data(), static_cast<std::streamsize>(bytes.size())))
    throw Error("cannot read " + what + " file", SourceLocation{path});
  const std::string expected = magic.empty() ? std::string("ANTP") : magic;
  if (bytes.size() < kHeaderSize || std::string(bytes.data(), expected.size()) != expected)
    fail_file(path, what,
              "not an antipode " + what + " file (it does not start with '" + expected + "')");
  Container file;
  file.version = read_at<std::uint32_t>(bytes, kMagicSize);
  const auto size = read_at<std::uint64_t>(bytes, kMagicSize + 4);
  const auto checksum = read_at<std::uint64_t>(bytes, kMagicSize + 12);
  if (bytes.size() - kHeaderSize != size) {
    fail_file(path, what,
              "truncated or extended: " + std::to_string(bytes.size() - kHeaderSize) +
                  " payload bytes, the header says " + std::to_string(size));
  }
  bytes.erase(bytes.begin(), bytes.begin() + kHeaderSize);
  file.payload = std::move(bytes);
  if (fnv1a(file.payload) != checksum)
    fail_file(path, what, "corrupted (checksum mismatch); re-create the file");
  return file;
}

}  // namespace

void check_binary_file(const std::string& path, const std::string& what) {
  read_container(path, what, "");
}

BinaryWriter::BinaryWriter(std::string magic, std::uint32_t version)
    : magic_(std::move(magic)), version_(version) {
  if (magic_.size() != kMagicSize) throw InternalError("binary file magic must be 8 characters");
}

void BinaryWriter::put_string(const std::string& text) {
  put<std::uint64_t>(text.size());
  append(text.data(), text.size());
}

void BinaryWriter::append(const void* data, std::size_t bytes) {
  const char* begin = static_cast<const char*>(data);
  payload_.insert(payload_.end(), begin, begin + bytes);
}

void BinaryWriter::write(const std::string& path) const {
  write_file_atomically(path, [&](const std::string& temporary) {
    std::ofstream out(temporary, std::ios::binary);
    const std::uint64_t size = payload_.size();
    const std::uint64_t checksum = fnv1a(payload_);
    out.write(magic_.data(), kMagicSize);
    out.write(reinterpret_cast<const char*>(&version_), sizeof(version_));
    out.write(reinterpret_cast<const char*>(&size), sizeof(size));
    out.write(reinterpret_cast<const char*>(&checksum), sizeof(checksum));
    out.write(payload_.data(), static_cast<std::streamsize>(payload_.size()));
    out.flush();
    if (!out) throw Error("cannot write " + temporary);
  });
}

BinaryReader::BinaryReader(const std::string& path, const std::string& magic,
                           std::uint32_t newest_version, std::string what)
    : path_(path), what_(std::move(what)) {
  Container file = read_container(path, what_, magic);
  version_ = file.version;
  if (version_ == 0 || version_ > newest_version) {
    fail("format version " + std::to_string(version_) + ", but this antipode reads versions 1-" +
         std::to_string(newest_version) + " (update antipode or re-create the file)");
  }
  payload_ = std::move(file.payload);
}

std::string BinaryReader::get_string() {
  const auto size = get<std::uint64_t>();
  if (size > remaining()) fail("a length runs past the end of the file");
  std::string text(payload_.data() + offset_, static_cast<std::size_t>(size));
  offset_ += static_cast<std::size_t>(size);
  return text;
}

void BinaryReader::take(void* data, std::size_t bytes) {
  if (bytes > remaining()) fail("ends early");
  if (bytes > 0) std::memcpy(data, payload_.data() + offset_, bytes);
  offset_ += bytes;
}

void BinaryReader::expect_end() const {
  if (remaining() != 0) fail(std::to_string(remaining()) + " unexpected bytes at the end");
}

void BinaryReader::fail(const std::string& message) const { fail_file(path_, what_, message); }

}  // namespace antipode
