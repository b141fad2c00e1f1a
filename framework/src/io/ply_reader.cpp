// PLY files, read here rather than by PCL's PLYReader: linking PCL's io library (and through
// it VTK, OpenNI and libusb, 40 shared libraries) added 20 ms to the start of every antipode
// process, 20.0 ms against 0.7 ms for a bare process (`perf stat -r 21` of a program that
// only dlopens libpcl_io.so), while the header parser below was needed anyway: PCL's reader
// aborted the process on some inputs (tests/fuzz/corpus/cloud). No other PLY library is
// packaged for Debian short of VTK or Assimp. The header is checked (magic, format, element
// sizes against the file size) before any record is read, so a short or garbled file is an
// Error rather than a giant allocation; only the vertices' x, y and z are kept.
#include <cstring>
#include <limits>

#include "antipode/core/error.hpp"
#include "raw_points.hpp"
#include "text_scan.hpp"

namespace antipode::io {
namespace {

constexpr std::uint64_t kMaxPoints = std::numeric_limits<std::int32_t>::max();
constexpr std::size_t kMaxHeaderBytes = std::size_t{64} * 1024;

// One property of an element: a scalar of `size` bytes, or a list whose length is a
// `size`-byte unsigned count followed by that many `item_size`-byte items.
struct PlyProperty {
  std::string name;
  std::uint64_t size = 0;
  std::uint64_t item_size = 0;  // 0: not a list
  bool floating = false;        // a scalar float or double
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
  int data_line = 0;  // the line end_header is on
};

std::uint64_t scalar_size(std::string_view type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "int32" || type == "uint32") return 4;
  if (type == "float" || type == "float32") return 4;
  if (type == "double" || type == "float64") return 8;
  return 0;
}

bool is_floating(std::string_view type) {
  return type == "float" || type == "float32" || type == "double" || type == "float64";
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
        header_.data_line = line_;
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
    element.properties.push_back({std::string(words.back()), size, list ? scalar_size(words[3]) : 0,
                                  !list && is_floating(words[1])});
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
  // A vertex is a point here: a record of numbers, of a size fixed by the header.
  for (const auto& property : vertex->properties) {
    if (property.item_size != 0)
      throw Error("the PLY vertices have a list property ('" + property.name +
                      "'): a vertex must hold only numbers",
                  {path});
  }
  for (const char* name : {"x", "y", "z"}) {
    const PlyProperty* found = nullptr;
    for (const auto& property : vertex->properties)
      if (property.name == name && found == nullptr) found = &property;
    if (found == nullptr)
      throw Error(std::string("the PLY vertices have no '") + name + "' property", {path});
    if (!found->floating)
      throw Error(std::string("field '") + name + "' is not floating point", {path});
  }
  const std::uint64_t available = bytes.size() - header.data_offset;
  if (available < needed) {
    throw Error("truncated PLY file: its header declares at least " + std::to_string(needed) +
                    " bytes of data but the file holds " + std::to_string(available),
                {path});
  }
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

// Skips the records of `element` from `at`, list lengths included, and throws unless they
// all lie in the file.
void skip_binary_element(const std::string& path, const std::string& bytes, const PlyHeader& header,
                         const PlyElement& element, std::uint64_t& at) {
  const std::uint64_t end = bytes.size();
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

// Where a coordinate lies in a vertex record, and how it is stored.
struct Coordinate {
  std::uint64_t offset = 0;  // binary: bytes from the record's start
  std::size_t index = 0;     // ascii: values from the record's start
  bool is_double = false;
};

Coordinate find_coordinate(const PlyElement& vertex, const char* name) {
  Coordinate c;
  for (const auto& property : vertex.properties) {
    if (property.name == name) {
      c.is_double = property.size == 8;
      return c;
    }
    c.offset += property.size;
    ++c.index;
  }
  return c;  // not reached: check_ply found every coordinate
}

// The float or double at `at`, in the file's byte order, as a float.
float binary_value(const char* at, bool is_double, bool big_endian) {
  char raw[8];
  const std::size_t size = is_double ? 8 : 4;
  for (std::size_t k = 0; k < size; ++k) raw[k] = at[big_endian ? size - 1 - k : k];
  if (is_double) {
    double value = 0.0;
    std::memcpy(&value, raw, sizeof value);
    return static_cast<float>(value);
  }
  float value = 0.0f;
  std::memcpy(&value, raw, sizeof value);
  return value;
}

// The vertices of a binary file; every other element's records are walked too, so that a
// list running past the end is an error wherever it lies.
std::vector<Eigen::Vector3f> binary_vertices(const std::string& path, const std::string& bytes,
                                             const PlyHeader& header) {
  std::uint64_t at = header.data_offset;
  std::vector<Eigen::Vector3f> points;
  for (const auto& element : header.elements) {
    if (element.name != "vertex") {
      skip_binary_element(path, bytes, header, element, at);
      continue;
    }
    const std::uint64_t step = element.min_record_bytes;  // no lists among vertex properties
    if (element.count * step > bytes.size() - std::min<std::uint64_t>(at, bytes.size())) {
      throw Error("truncated PLY file: its vertices run past the end of the file", {path});
    }
    const Coordinate c[3] = {find_coordinate(element, "x"), find_coordinate(element, "y"),
                             find_coordinate(element, "z")};
    points.resize(element.count);
    for (std::uint64_t i = 0; i < element.count; ++i, at += step) {
      for (int axis = 0; axis < 3; ++axis) {
        points[i][axis] =
            binary_value(bytes.data() + at + c[axis].offset, c[axis].is_double, header.big_endian);
      }
    }
  }
  return points;
}

// An ascii file's values, word by word, with the line each came from.
class AsciiWords {
 public:
  AsciiWords(const std::string& path, const std::string& bytes, const PlyHeader& header)
      : path_(path), bytes_(bytes), next_(header.data_offset), line_(header.data_line) {}

  std::string_view next(const PlyElement& element, std::uint64_t record) {
    while (word_ == words_.size()) {
      if (next_ >= bytes_.size()) {
        throw Error("truncated PLY file: element '" + element.name + "' record " +
                        std::to_string(record) + " runs past the end of the file",
                    {path_});
      }
      words_ = split_words(line_at(bytes_, next_, next_));
      word_ = 0;
      ++line_;
    }
    return words_[word_++];
  }

  [[noreturn]] void fail(const std::string& message) const {
    throw Error(message, {path_, line_, 0});
  }

 private:
  const std::string& path_;
  const std::string& bytes_;
  std::size_t next_;
  std::vector<std::string_view> words_;
  std::size_t word_ = 0;
  int line_;  // of the words being read
};

// The vertices of an ascii file, whose every element's values are read (records may span
// lines, as the words are read one after the other).
std::vector<Eigen::Vector3f> ascii_vertices(const std::string& path, const std::string& bytes,
                                            const PlyHeader& header) {
  AsciiWords words(path, bytes, header);
  std::vector<Eigen::Vector3f> points;
  for (const auto& element : header.elements) {
    const bool vertex = element.name == "vertex";
    Coordinate c[3];
    if (vertex) {
      c[0] = find_coordinate(element, "x"), c[1] = find_coordinate(element, "y");
      c[2] = find_coordinate(element, "z");
      points.resize(element.count);
    }
    for (std::uint64_t record = 0; record < element.count; ++record) {
      for (std::size_t p = 0; p < element.properties.size(); ++p) {
        const std::string_view word = words.next(element, record);
        std::uint64_t items = 0;
        if (element.properties[p].item_size != 0) {
          const auto count = parse_unsigned(word);
          if (!count) words.fail("a list's count is not a number: " + quote_for_message(word));
          items = *count;
        }
        for (std::uint64_t i = 0; i < items; ++i) words.next(element, record);
        for (int axis = 0; vertex && axis < 3; ++axis) {
          if (c[axis].index != p) continue;
          const auto value = parse_float(word);
          if (!value) words.fail("not a number: " + quote_for_message(word));
          points[record][axis] = *value;
        }
      }
    }
  }
  return points;
}

}  // namespace

RawPoints read_ply(const std::string& path, const std::string& bytes) {
  const PlyHeader header = PlyHeaderParser(path, bytes).parse();
  check_ply(path, bytes, header);
  RawPoints raw;
  raw.points_m =
      header.ascii ? ascii_vertices(path, bytes, header) : binary_vertices(path, bytes, header);
  return raw;
}

}  // namespace antipode::io
