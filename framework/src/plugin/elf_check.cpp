#include "elf_check.hpp"

#include <elf.h>

#include <cstring>
#include <fstream>
#include <vector>

namespace antipode::detail {

std::string elf_problem(const std::string& path) {
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  if (!file) return "";  // dlopen says why
  const auto size = static_cast<std::uint64_t>(file.tellg());
  Elf64_Ehdr header{};
  file.seekg(0);
  if (!file.read(reinterpret_cast<char*>(&header), sizeof header)) return "";
  if (std::memcmp(header.e_ident, ELFMAG, SELFMAG) != 0 || header.e_ident[EI_CLASS] != ELFCLASS64)
    return "";
  const std::uint64_t table_end =
      header.e_phoff + std::uint64_t(header.e_phnum) * std::uint64_t(header.e_phentsize);
  if (header.e_phentsize != sizeof(Elf64_Phdr) || table_end > size)
    return "the file is truncated or damaged: its program headers end at byte " +
           std::to_string(table_end) + " of " + std::to_string(size);
  std::vector<Elf64_Phdr> segments(header.e_phnum);
  file.seekg(std::streamoff(header.e_phoff));
  if (!file.read(reinterpret_cast<char*>(segments.data()),
                 std::streamsize(segments.size() * sizeof(Elf64_Phdr))))
    return "the file is truncated: its program headers cannot be read";
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const Elf64_Phdr& segment = segments[i];
    if (segment.p_type != PT_LOAD) continue;
    const std::uint64_t end = segment.p_offset + segment.p_filesz;
    if (end > size)
      return "the file is truncated: loadable segment " + std::to_string(i) + " ends at byte " +
             std::to_string(end) + " of " + std::to_string(size);
  }
  return "";
}

}  // namespace antipode::detail
