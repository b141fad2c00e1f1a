// PLY files: the header is checked here (magic, format, element sizes against the file
// size) before PCL's PLYReader parses the file, so that a short or garbled file is an
// Error rather than a giant allocation.
#include <limits>

#include <pcl/io/ply_io.h>

#include "antipode/core/error.hpp"
#include "pcl_blob.hpp"
#include "raw_points.hpp"
#include "text_scan.hpp"

namespace antipode::io {
namespace {

constexpr std::uint64_t kMaxPoints = std::numeric_limits<std::int32_t>::max();
constexpr std::size_t kMaxHeaderBytes = 64 * 1024;

// One property of an element: a scalar of `size` bytes, or a list whose length is a
// `size`-byte unsigned count followed by that many `item_size`-byte items.
struct PlyProperty {
  std::string name;
  std::uint64_t size = 0;
  std::uint64_t item_size = 0;  // 0: not a list
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::uint64_t min_record_bytes = 0;  // binary: scalars plus the count of each list
  std::uint64_t values = 0;            // ascii: values per record at least
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  bool ascii = true;
  bool big_endian = false;
  std::vector<PlyElement> elements;
  std::size_t data_offset = 0;
};

std::uint64_t scalar_size(std::string_view type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "int32" || type == "uint32") return 4;
  if (type == "float" || type == "float32") return 4;
  if (type == "double" || type == "float64") return 8;
  return 0;
}

class PlyHeaderParser {
 public:
  PlyHeaderParser(const std::string& path, const std::string& bytes) : path_(path), bytes_(bytes) {}

  PlyHeader parse() {
    std::size_t offset = 0;
    if (line(offset) != "ply") throw Error("not a PLY file: it does not start with 'ply'", {path_});
    while (offset < bytes_.size() && offset < kMaxHeaderBytes) {
      const std::vector<std::string_view> words = split_words(line(offset));
      if (words.empty() || words[0] == "comment" || words[0] == "obj_info") continue;
      if (words[0] == "end_header") {
        header_.data_offset = offset;
        return header_;
      }
      handle(words);
    }
    throw Error("not a PLY file: no end_header line", {path_});
  }

 private:
  std::string_view line(std::size_t& offset) {
    std::size_t next = 0;
    const std::string_view text = line_at(bytes_, offset, next);
    offset = next;
    ++line_;
    return text;
  }

  [[noreturn]] void fail(const std::string& message) const {
    throw Error(message, {path_, line_, 0});
  }

  void handle(const std::vector<std::string_view>& words) {
    if (words[0] == "format") return set_format(words);
    if (words[0] == "element") return add_element(words);
    if (words[0] == "property") return add_property(words);
    fail("not a PLY header line: " + quote_for_message(words[0]));
  }

  void set_format(const std::vector<std::string_view>& words) {
    if (words.size() != 3) fail("format needs a kind and a version");
    if (words[1] == "ascii")
      header_.ascii = true;
    else if (words[1] == "binary_little_endian" || words[1] == "binary_big_endian")
      header_.ascii = false, header_.big_endian = words[1] == "binary_big_endian";
    else
      fail("format " + quote_for_message(words[1]) + " is unknown");
  }

  void add_element(const std::vector<std::string_view>& words) {
    const auto count = words.size() == 3 ? parse_unsigned(words[2]) : std::nullopt;
    if (!count || *count > kMaxPoints) fail("element needs a name and a count");
    PlyElement element;
    element.name = std::string(words[1]);
    element.count = *count;
    header_.elements.push_back(std::move(element));
  }

  void add_property(const std::vector<std::string_view>& words) {
    if (header_.elements.empty()) fail("property before any element");
    PlyElement& element = header_.elements.back();
    const bool list = words.size() == 5 && words[1] == "list";
    if (!list && words.size() != 3) fail("property needs a type and a name");
    const std::uint64_t size = scalar_size(list ? words[2] : words[1]);
    if (size == 0 || (list && scalar_size(words[3]) == 0)) fail("property type is unknown");
    if (list && size > 4) fail("a list's count must be an integer of at most 4 bytes");
    element.min_record_bytes += size;
    element.values += 1;
    element.properties.push_back(
        {std::string(words.back()), size, list ? scalar_size(words[3]) : 0});
  }

  const std::string& path_;
  const std::string& bytes_;
  int line_ = 0;
  PlyHeader header_;
};

void check_ply(const std::string& path, const std::string& bytes, const PlyHeader& header) {
  const PlyElement* vertex = nullptr;
  std::uint64_t needed = 0;
  for (const auto& element : header.elements) {
    if (element.name == "vertex") vertex = &element;
    needed += element.count * (header.ascii ? element.values : element.min_record_bytes);
  }
  if (vertex == nullptr) throw Error("the PLY file has no vertex element", {path});
  // PCL's reader aborts the process on a list among the vertex properties (found by
  // fuzzing: tests/fuzz/corpus/cloud/ply-vertex-list); a vertex is a point here.
  for (const auto& property : vertex->properties) {
    if (property.item_size != 0)
      throw Error("the PLY vertices have a list property ('" + property.name +
                      "'): a vertex must hold only numbers",
                  {path});
  }
  for (const char* name : {"x", "y", "z"}) {
    bool found = false;
    for (const auto& property : vertex->properties) found = found || property.name == name;
    if (!found)
      throw Error(std::string("the PLY vertices have no '") + name + "' property", {path});
  }
  const std::uint64_t available = bytes.size() - header.data_offset;
  if (available < needed) {
    throw Error("truncated PLY file: its header declares at least " + std::to_string(needed) +
                    " bytes of data but the file holds " + std::to_string(available),
                {path});
  }
}

// True when some element has a list property: only then can records vary in length (without
// lists check_ply's size test is exact).
bool has_lists(const PlyHeader& header) {
  for (const auto& element : header.elements)
    for (const auto& property : element.properties)
      if (property.item_size != 0) return true;
  return false;
}

// The unsigned `size`-byte count at `at` in the file's byte order.
std::uint64_t list_count(const std::string& bytes, std::size_t at, std::uint64_t size,
                         bool big_endian) {
  std::uint64_t value = 0;
  for (std::uint64_t k = 0; k < size; ++k) {
    const auto byte = static_cast<unsigned char>(bytes[at + (big_endian ? k : size - 1 - k)]);
    value = (value << 8) | byte;
  }
  return value;
}

// Walks a binary file's records, list lengths included, and throws unless they all lie in
// the file (PCL's reader aborts the process on a list that runs past the end).
void check_binary_records(const std::string& path, const std::string& bytes,
                          const PlyHeader& header) {
  std::uint64_t at = header.data_offset;
  const std::uint64_t end = bytes.size();
  for (const auto& element : header.elements)
    for (std::uint64_t record = 0; record < element.count; ++record)
      for (const auto& property : element.properties) {
        if (at + property.size > end) {
          throw Error("truncated PLY file: element '" + element.name + "' record " +
                          std::to_string(record) + " runs past the end of the file",
                      {path});
        }
        const std::uint64_t items =
            property.item_size == 0 ? 0 : list_count(bytes, at, property.size, header.big_endian);
        at += property.size + items * property.item_size;
        if (at > end) {
          throw Error("truncated PLY file: the list '" + property.name + "' of element '" +
                          element.name + "' record " + std::to_string(record) + " declares " +
                          std::to_string(items) + " items, past the end of the file",
                      {path});
        }
      }
}

}  // namespace

RawPoints read_ply(const std::string& path, const std::string& bytes) {
  const PlyHeader header = PlyHeaderParser(path, bytes).parse();
  check_ply(path, bytes, header);
  if (!header.ascii && has_lists(header)) check_binary_records(path, bytes, header);
  RawPoints raw;
  for (const auto& element : header.elements) {
    if (element.name == "vertex" && element.count == 0) return raw;
  }
  silence_pcl_console();
  pcl::PCLPointCloud2 blob;
  Eigen::Vector4f origin;
  Eigen::Quaternionf orientation;
  int version = 0;
  pcl::PLYReader reader;
  if (reader.read(path, blob, origin, orientation, version, 0) < 0) {
    throw Error("corrupt PLY file: PCL cannot parse its data", {path});
  }
  raw.points_m = coordinates_of(path, blob);
  return raw;
}

}  // namespace antipode::io
