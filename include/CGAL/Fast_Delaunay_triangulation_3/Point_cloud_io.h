// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Readers of point clouds into one flat array x0 y0 z0 x1 y1 z1 ..., the
// form the triangulation's bulk insertion works on:
//   .xyz  x y z per line, further columns (normals, colours) ignored, blank
//         lines and lines starting with # skipped, separators blanks or commas
//   .ply  ascii, binary_little_endian or binary_big_endian; the vertex
//         element's x, y, z (float / double, alias float32 / float64), other
//         properties and elements skipped, faces ignored
//   .off  the vertices (OFF and its NOFF, COFF, ... variants); faces ignored
//   .npy  NumPy format 1, 2 or 3, dtype <f8 or <f4 (also >f8, >f4), shape
//         (n, 3), C or Fortran order
// The file is read in blocks of a few megabytes (no per-point allocation;
// numbers by std::from_chars), so that 1e7 points take a second or two.
// Bad input throws Point_file_error naming the file, the line (text) or the
// byte offset (binary) and the problem.  Finiteness is not checked here: the
// triangulation refuses NaN and infinite coordinates itself.
//
//   #include <CGAL/Fast_Delaunay_triangulation_3/Point_cloud_io.h>
//   std::vector<double> xyz = CGAL::Fast_Delaunay_triangulation_3_io::read_points("scan.ply");

#ifndef CGAL_FAST_DELAUNAY_TRIANGULATION_3_POINT_CLOUD_IO_H
#define CGAL_FAST_DELAUNAY_TRIANGULATION_3_POINT_CLOUD_IO_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Byte_order.h>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_io {

// Bad or unreadable input: what() is "FILE: line N: problem" or
// "FILE: byte offset N: problem".
class Point_file_error : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

// Called after each block read with (bytes read so far, file size).
typedef std::function<void(std::size_t done, std::size_t total)> Read_progress;

} // namespace Fast_Delaunay_triangulation_3_io

namespace Fast_Delaunay_triangulation_3_internal {
namespace point_files {

using Fast_Delaunay_triangulation_3_io::Point_file_error;
using Fast_Delaunay_triangulation_3_io::Read_progress;

// A value of type T stored in `bytes` with the given byte order.
template <class T>
T load(const char* bytes, bool little_endian)
{
  char b[sizeof(T)];
  std::memcpy(b, bytes, sizeof(T));
  if(little_endian != machine_is_little_endian())
    std::reverse(b, b + sizeof(T));
  T value;
  std::memcpy(&value, b, sizeof(T));
  return value;
}

// The file as a sequence of lines or of bytes, read in blocks into one
// buffer that holds at least the current line or the bytes asked for.
class File_reader
{
public:
  static constexpr std::size_t block_size = std::size_t(8) << 20;

  File_reader(const std::string& path, const Read_progress& progress) : path_(path), progress_(progress)
  {
    file_ = std::fopen(path.c_str(), "rb");
    if(file_ == nullptr) throw Point_file_error(path + ": cannot open the file");
    if(std::fseek(file_, 0, SEEK_END) == 0) {
      const long size = std::ftell(file_);
      if(size > 0) size_ = std::size_t(size);
      std::fseek(file_, 0, SEEK_SET);
    }
  }
  ~File_reader() { std::fclose(file_); }
  File_reader(const File_reader&) = delete;
  File_reader& operator=(const File_reader&) = delete;

  const std::string& path() const { return path_; }
  std::size_t size() const { return size_; }
  std::size_t line_number() const { return line_; }
  // Bytes consumed so far: the offset of the next byte.
  std::size_t offset() const { return consumed_before_buffer_ + begin_; }

  // The next line without its end of line ("\n" or "\r\n"); false at the end.
  bool next_line(std::string_view& line)
  {
    for(;;) {
      const char* start = buffer_.data() + begin_;
      const void* eol = end_ > begin_ ? std::memchr(start, '\n', end_ - begin_) : nullptr;
      if(eol != nullptr) {
        const std::size_t length = static_cast<const char*>(eol) - start;
        line = trim_cr(std::string_view(start, length));
        begin_ += length + 1;
        ++line_;
        return true;
      }
      if(at_end_) {
        if(begin_ == end_) return false;
        line = trim_cr(std::string_view(start, end_ - begin_));
        begin_ = end_;
        ++line_;
        return true;
      }
      refill(end_ - begin_ + block_size);
    }
  }

  // The next n bytes, contiguous; throws if the file ends before.
  const char* take(std::size_t n, const char* what)
  {
    if(end_ - begin_ < n) {
      refill(std::max(n, block_size));
      if(end_ - begin_ < n)
        throw error_at_offset(offset(), std::string("the file ends inside ") + what + " (truncated binary data)");
    }
    const char* p = buffer_.data() + begin_;
    begin_ += n;
    return p;
  }
  // Bytes available without reading: at least min(n, bytes left), up to n.
  std::size_t available(std::size_t n)
  {
    if(end_ - begin_ < n && !at_end_) refill(std::max(n, block_size));
    return std::min(n, end_ - begin_);
  }

  Point_file_error error_at_line(const std::string& problem) const { return error_at_line(line_, problem); }
  Point_file_error error_at_line(std::size_t line, const std::string& problem) const
  {
    return Point_file_error(path_ + ": line " + std::to_string(line) + ": " + problem);
  }
  Point_file_error error_at_offset(std::size_t offset, const std::string& problem) const
  {
    return Point_file_error(path_ + ": byte offset " + std::to_string(offset) + ": " + problem);
  }

private:
  static std::string_view trim_cr(std::string_view s)
  {
    if(!s.empty() && s.back() == '\r') s.remove_suffix(1);
    return s;
  }

  // Keeps the unconsumed bytes and reads until `wanted` bytes are buffered
  // or the file ends.
  void refill(std::size_t wanted)
  {
    const std::size_t kept = end_ - begin_;
    if(begin_ > 0) std::memmove(buffer_.data(), buffer_.data() + begin_, kept);
    consumed_before_buffer_ += begin_;
    begin_ = 0;
    end_ = kept;
    if(buffer_.size() < wanted) buffer_.resize(wanted);
    while(end_ < wanted && !at_end_) {
      const std::size_t got = std::fread(buffer_.data() + end_, 1, wanted - end_, file_);
      end_ += got;
      read_ += got;
      if(got == 0) {
        if(std::ferror(file_)) throw Point_file_error(path_ + ": read error");
        at_end_ = true;
      }
    }
    if(progress_) progress_(std::min(read_, size_), size_);
  }

  std::string path_;
  Read_progress progress_;
  std::FILE* file_ = nullptr;
  std::size_t size_ = 0, read_ = 0;
  std::vector<char> buffer_;
  std::size_t begin_ = 0, end_ = 0, consumed_before_buffer_ = 0;
  std::size_t line_ = 0;
  bool at_end_ = false;
};

inline bool is_separator(char c) { return c == ' ' || c == '\t' || c == ',' || c == '\r' || c == '\v' || c == '\f'; }
inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// The words of a line, one at a time.
class Words
{
public:
  Words(std::string_view line, bool commas = false) : s_(line), commas_(commas) {}
  bool next(std::string_view& word)
  {
    auto separator = [this](char c) { return commas_ ? is_separator(c) : is_blank(c); };
    while(i_ < s_.size() && separator(s_[i_])) ++i_;
    if(i_ == s_.size()) return false;
    const std::size_t start = i_;
    while(i_ < s_.size() && !separator(s_[i_])) ++i_;
    word = s_.substr(start, i_ - start);
    return true;
  }
  bool done()
  {
    std::string_view w;
    return !next(w);
  }

private:
  std::string_view s_;
  std::size_t i_ = 0;
  bool commas_;
};

inline bool parse_double(std::string_view word, double& x)
{
  const char* first = word.data();
  const char* last = first + word.size();
  if(first != last && *first == '+') ++first; // from_chars takes no '+'
  const std::from_chars_result r = std::from_chars(first, last, x);
  return r.ec == std::errc() && r.ptr == last;
}

template <class Integer>
bool parse_integer(std::string_view word, Integer& x)
{
  const std::from_chars_result r = std::from_chars(word.data(), word.data() + word.size(), x);
  return r.ec == std::errc() && r.ptr == word.data() + word.size();
}

inline std::string quoted(std::string_view word)
{
  const std::size_t shown = 40;
  return "'" + std::string(word.substr(0, shown)) + (word.size() > shown ? "...'" : "'");
}

// The first three numbers of a line into p; throws naming the line.
inline void parse_three_coordinates(File_reader& in, std::string_view line, double* p, bool commas)
{
  Words words(line, commas);
  std::string_view word;
  for(int a = 0; a < 3; ++a) {
    if(!words.next(word))
      throw in.error_at_line(std::to_string(a) + (a == 1 ? " column" : " columns") +
                             ", expected at least 3 (x y z)");
    if(!parse_double(word, p[a])) throw in.error_at_line(quoted(word) + " is not a number");
  }
}

inline bool is_comment_or_blank(std::string_view line)
{
  std::size_t i = 0;
  while(i < line.size() && is_blank(line[i])) ++i;
  return i == line.size() || line[i] == '#';
}

inline std::string lower_extension(const std::string& path)
{
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of("/\\");
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash)) return std::string();
  std::string e = path.substr(dot + 1);
  for(char& c : e) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return e;
}

} // namespace point_files
} // namespace Fast_Delaunay_triangulation_3_internal

namespace Fast_Delaunay_triangulation_3_io {

namespace point_files = Fast_Delaunay_triangulation_3_internal::point_files;

// x y z per line; further columns ignored; blank and # lines skipped.
inline std::vector<double> read_xyz(const std::string& path, const Read_progress& progress = Read_progress())
{
  point_files::File_reader in(path, progress);
  std::vector<double> xyz;
  std::string_view line;
  bool reserved = false;
  while(in.next_line(line)) {
    if(point_files::is_comment_or_blank(line)) continue;
    if(!reserved && in.size() > 0) {
      // About the file size over the first line's length, with a margin:
      // one allocation instead of the doublings of push_back.
      xyz.reserve(3 * (in.size() / (line.size() + 1) + 1) * 9 / 8);
      reserved = true;
    }
    const std::size_t n = xyz.size();
    xyz.resize(n + 3);
    point_files::parse_three_coordinates(in, line, xyz.data() + n, true);
  }
  // A copy to give back the margin only when it is large.
  if(xyz.capacity() > xyz.size() + xyz.size() / 2) xyz.shrink_to_fit();
  return xyz;
}

// The vertices of an OFF file (header OFF, COFF, NOFF, NCOFF, STOFF, ...,
// then "vertices faces edges"); faces ignored.
inline std::vector<double> read_off(const std::string& path, const Read_progress& progress = Read_progress())
{
  point_files::File_reader in(path, progress);
  std::string_view line, word;
  auto next_content_line = [&](const char* what) {
    do {
      if(!in.next_line(line)) throw in.error_at_line(std::string("the file ends before ") + what);
    } while(point_files::is_comment_or_blank(line));
  };
  next_content_line("the OFF header");
  point_files::Words header(line);
  header.next(word);
  const bool is_off = word.size() >= 3 && word.substr(word.size() - 3) == "OFF" &&
                      word.find_first_not_of("STCNU4") == word.size() - 3;
  if(!is_off)
    throw in.error_at_line("wrong header " + point_files::quoted(word) + ", expected OFF (or COFF, NOFF, ...)");
  if(word.find('4') != std::string_view::npos) throw in.error_at_line("4OFF (points in 4D) is not supported");
  std::string_view count_word;
  if(!header.next(count_word)) {
    next_content_line("the vertex count");
    header = point_files::Words(line);
    header.next(count_word);
  }
  if(count_word == "BINARY") throw in.error_at_line("binary OFF is not supported");
  std::size_t n = 0;
  if(!point_files::parse_integer(count_word, n))
    throw in.error_at_line("the vertex count " + point_files::quoted(count_word) + " is not a number");
  std::vector<double> xyz(3 * n);
  for(std::size_t i = 0; i < n; ++i) {
    next_content_line(("vertex " + std::to_string(i) + " of " + std::to_string(n)).c_str());
    point_files::parse_three_coordinates(in, line, xyz.data() + 3 * i, false);
  }
  return xyz;
}

} // namespace Fast_Delaunay_triangulation_3_io

namespace Fast_Delaunay_triangulation_3_internal {
namespace point_files {

// PLY scalar types, by their two names.
struct Ply_type
{
  int bytes = 0; // 0: unknown
  bool is_float = false, is_signed = false;
};

inline Ply_type ply_type(std::string_view name)
{
  struct Named { const char* a; const char* b; Ply_type t; };
  static const Named types[] = {
      {"char", "int8", {1, false, true}},      {"uchar", "uint8", {1, false, false}},
      {"short", "int16", {2, false, true}},    {"ushort", "uint16", {2, false, false}},
      {"int", "int32", {4, false, true}},      {"uint", "uint32", {4, false, false}},
      {"float", "float32", {4, true, true}},   {"double", "float64", {8, true, true}}};
  for(const Named& n : types)
    if(name == n.a || name == n.b) return n.t;
  return Ply_type();
}

struct Ply_property
{
  std::string name;
  Ply_type type;             // of the value (of each entry for a list)
  Ply_type count_type;       // lists only
  bool is_list = false;
  std::size_t line = 0;      // in the header
};

struct Ply_element
{
  std::string name;
  std::size_t count = 0;
  std::vector<Ply_property> properties;
};

// A PLY list count: an integer of type t, read from `in`; throws if negative.
inline std::size_t ply_list_count(File_reader& in, const Ply_type& t, bool little)
{
  const std::size_t at = in.offset();
  const char* bytes = in.take(std::size_t(t.bytes), "a list count");
  std::int64_t count;
  switch(t.bytes) {
  case 1: count = t.is_signed ? load<std::int8_t>(bytes, little) : load<std::uint8_t>(bytes, little); break;
  case 2: count = t.is_signed ? load<std::int16_t>(bytes, little) : load<std::uint16_t>(bytes, little); break;
  default: count = t.is_signed ? load<std::int32_t>(bytes, little) : load<std::uint32_t>(bytes, little);
  }
  if(count < 0) throw in.error_at_offset(at, "negative list count " + std::to_string(count));
  return std::size_t(count);
}

inline double ply_coordinate(const char* bytes, const Ply_type& t, bool little)
{
  return t.bytes == 8 ? load<double>(bytes, little) : double(load<float>(bytes, little));
}

// Skips one item of `e` in a binary file.
inline void skip_binary_item(File_reader& in, const Ply_element& e, bool little)
{
  for(const Ply_property& p : e.properties) {
    if(!p.is_list) {
      in.take(std::size_t(p.type.bytes), ("element " + e.name).c_str());
      continue;
    }
    const std::size_t count = ply_list_count(in, p.count_type, little);
    in.take(count * std::size_t(p.type.bytes), ("a list of element " + e.name).c_str());
  }
}

} // namespace point_files
} // namespace Fast_Delaunay_triangulation_3_internal

namespace Fast_Delaunay_triangulation_3_io {

// The vertex element's x, y, z of a PLY file (ascii or binary).
inline std::vector<double> read_ply(const std::string& path, const Read_progress& progress = Read_progress())
{
  using namespace point_files;
  File_reader in(path, progress);
  std::string_view line, word;
  if(!in.next_line(line) || line != "ply") throw in.error_at_line("wrong header, expected 'ply' on the first line");
  enum Format { ascii, little, big } format = ascii;
  bool has_format = false;
  std::vector<Ply_element> elements;
  for(;;) {
    if(!in.next_line(line)) throw in.error_at_line("the file ends inside the header (no end_header)");
    Words words(line);
    if(!words.next(word) || word == "comment" || word == "obj_info") continue;
    if(word == "end_header") break;
    if(word == "format") {
      std::string_view name, version;
      words.next(name);
      words.next(version);
      if(name == "ascii") format = ascii;
      else if(name == "binary_little_endian") format = little;
      else if(name == "binary_big_endian") format = big;
      else throw in.error_at_line("unknown PLY format " + quoted(name));
      has_format = true;
    } else if(word == "element") {
      Ply_element e;
      std::string_view name, count;
      if(!words.next(name) || !words.next(count) || !parse_integer(count, e.count))
        throw in.error_at_line("expected 'element NAME COUNT'");
      e.name = std::string(name);
      elements.push_back(e);
    } else if(word == "property") {
      if(elements.empty()) throw in.error_at_line("a property before any element");
      Ply_property p;
      std::string_view type, name;
      if(!words.next(type)) throw in.error_at_line("expected 'property TYPE NAME'");
      if(type == "list") {
        std::string_view count_type;
        if(!words.next(count_type) || !words.next(type))
          throw in.error_at_line("expected 'property list COUNT_TYPE TYPE NAME'");
        p.is_list = true;
        p.count_type = ply_type(count_type);
        if(p.count_type.bytes == 0 || p.count_type.is_float)
          throw in.error_at_line("list count type " + quoted(count_type) + " is not an integer type");
      }
      p.type = ply_type(type);
      if(p.type.bytes == 0) throw in.error_at_line("unknown property type " + quoted(type));
      if(!words.next(name)) throw in.error_at_line("expected 'property TYPE NAME'");
      p.name = std::string(name);
      p.line = in.line_number();
      elements.back().properties.push_back(p);
    } else {
      throw in.error_at_line("unexpected " + quoted(word) + " in the header");
    }
  }
  if(!has_format) throw in.error_at_line("no 'format' line in the header");
  const auto vertex =
      std::find_if(elements.begin(), elements.end(), [](const Ply_element& e) { return e.name == "vertex"; });
  if(vertex == elements.end()) throw in.error_at_line("no 'element vertex' in the header");
  int coordinate_property[3] = {-1, -1, -1};
  for(std::size_t k = 0; k < vertex->properties.size(); ++k) {
    const Ply_property& p = vertex->properties[k];
    const int axis = p.name == "x" ? 0 : p.name == "y" ? 1 : p.name == "z" ? 2 : -1;
    if(axis < 0) continue;
    if(p.is_list || !p.type.is_float)
      throw in.error_at_line(p.line, "vertex property " + p.name + " must be float or double (float32 / float64)");
    coordinate_property[axis] = int(k);
  }
  for(int a = 0; a < 3; ++a)
    if(coordinate_property[a] < 0)
      throw in.error_at_line(std::string("the vertex element has no property ") + "xyz"[a]);

  const std::size_t n = vertex->count;
  std::vector<double> xyz(3 * n);
  if(format == ascii) {
    // One item per line; elements before the vertices skipped line by line.
    for(auto e = elements.begin(); e != vertex; ++e)
      for(std::size_t i = 0; i < e->count; ++i)
        if(!in.next_line(line)) throw in.error_at_line("the file ends inside element " + e->name);
    for(std::size_t i = 0; i < n; ++i) {
      if(!in.next_line(line))
        throw in.error_at_line("the file ends after " + std::to_string(i) + " of " + std::to_string(n) + " vertices");
      Words words(line);
      for(std::size_t k = 0; k < vertex->properties.size(); ++k) {
        const Ply_property& p = vertex->properties[k];
        std::size_t values = 1;
        if(p.is_list) {
          if(!words.next(word) || !parse_integer(word, values))
            throw in.error_at_line("list count of property " + p.name + " missing or not a number");
        }
        for(std::size_t v = 0; v < values; ++v) {
          if(!words.next(word))
            throw in.error_at_line("vertex " + std::to_string(i) + " has too few values (property " + p.name + ")");
          int axis = -1;
          for(int a = 0; a < 3; ++a)
            if(coordinate_property[a] == int(k)) axis = a;
          if(axis >= 0 && !parse_double(word, xyz[3 * i + axis]))
            throw in.error_at_line(quoted(word) + " is not a number (property " + p.name + ")");
        }
      }
    }
    return xyz;
  }

  const bool is_little = format == little;
  for(auto e = elements.begin(); e != vertex; ++e)
    for(std::size_t i = 0; i < e->count; ++i) skip_binary_item(in, *e, is_little);
  bool has_list = false;
  std::size_t record = 0, at[3] = {0, 0, 0};
  for(std::size_t k = 0; k < vertex->properties.size(); ++k) {
    const Ply_property& p = vertex->properties[k];
    has_list = has_list || p.is_list;
    for(int a = 0; a < 3; ++a)
      if(coordinate_property[a] == int(k)) at[a] = record;
    record += std::size_t(p.type.bytes);
  }
  const Ply_type types[3] = {vertex->properties[coordinate_property[0]].type,
                             vertex->properties[coordinate_property[1]].type,
                             vertex->properties[coordinate_property[2]].type};
  if(!has_list) {
    // Fixed-size records: decoded a block at a time.
    std::size_t i = 0;
    while(i < n) {
      const std::size_t records = std::max<std::size_t>(1, std::min(n - i, File_reader::block_size / record));
      const std::size_t start = in.offset();
      if(in.available(records * record) < records * record)
        throw in.error_at_offset(start, "the file ends inside the vertices, " + std::to_string(n) +
                                            " announced (truncated binary data)");
      const char* bytes = in.take(records * record, "the vertices");
      for(std::size_t r = 0; r < records; ++r, ++i)
        for(int a = 0; a < 3; ++a) xyz[3 * i + a] = ply_coordinate(bytes + r * record + at[a], types[a], is_little);
    }
    return xyz;
  }
  for(std::size_t i = 0; i < n; ++i) {
    for(std::size_t k = 0; k < vertex->properties.size(); ++k) {
      const Ply_property& p = vertex->properties[k];
      if(p.is_list) {
        const std::size_t count = ply_list_count(in, p.count_type, is_little);
        in.take(count * std::size_t(p.type.bytes), "a list of the vertices");
        continue;
      }
      const char* bytes = in.take(std::size_t(p.type.bytes), "the vertices");
      for(int a = 0; a < 3; ++a)
        if(coordinate_property[a] == int(k)) xyz[3 * i + a] = ply_coordinate(bytes, p.type, is_little);
    }
  }
  return xyz;
}

} // namespace Fast_Delaunay_triangulation_3_io

namespace Fast_Delaunay_triangulation_3_internal {
namespace point_files {

// The value of 'key' in the NumPy header, a Python dict literal such as
// {'descr': '<f8', 'fortran_order': False, 'shape': (10, 3), }: the text
// after "'key':" up to the next ',' at depth 0 or the closing brace.
inline std::string npy_header_value(const std::string& header, const std::string& key)
{
  std::size_t k = header.find("'" + key + "'");
  if(k == std::string::npos) k = header.find("\"" + key + "\"");
  if(k == std::string::npos) return std::string();
  std::size_t i = header.find(':', k + key.size() + 2);
  if(i == std::string::npos) return std::string();
  ++i;
  int depth = 0;
  std::string value;
  for(; i < header.size(); ++i) {
    const char c = header[i];
    if(c == '(' || c == '[') ++depth;
    if(c == ')' || c == ']') --depth;
    if(depth == 0 && (c == ',' || c == '}')) break;
    if(c != ' ' && c != '\'' && c != '"') value += c;
    if(depth < 0) break;
  }
  return value;
}

} // namespace point_files
} // namespace Fast_Delaunay_triangulation_3_internal

namespace Fast_Delaunay_triangulation_3_io {

// An (n, 3) array of float64 or float32 in NumPy's .npy format.
inline std::vector<double> read_npy(const std::string& path, const Read_progress& progress = Read_progress())
{
  using namespace point_files;
  File_reader in(path, progress);
  const char* magic = in.take(8, "the NumPy magic string");
  if(std::memcmp(magic, "\x93NUMPY", 6) != 0) throw in.error_at_offset(0, "wrong header, not a NumPy .npy file");
  const int major = static_cast<unsigned char>(magic[6]);
  if(major < 1 || major > 3) throw in.error_at_offset(6, "unsupported .npy format version " + std::to_string(major));
  const std::size_t length = major == 1 ? load<std::uint16_t>(in.take(2, "the header length"), true)
                                        : load<std::uint32_t>(in.take(4, "the header length"), true);
  const std::size_t header_offset = in.offset();
  const std::string header(in.take(length, "the header"), length);
  const std::string descr = npy_header_value(header, "descr");
  const std::string order = npy_header_value(header, "fortran_order");
  const std::string shape = npy_header_value(header, "shape");
  const bool float_type = descr.size() == 3 && (descr[0] == '<' || descr[0] == '>') && descr[1] == 'f' &&
                          (descr[2] == '8' || descr[2] == '4');
  if(!float_type)
    throw in.error_at_offset(header_offset, "unsupported dtype '" + descr + "', expected <f8 or <f4");
  if(order != "False" && order != "True")
    throw in.error_at_offset(header_offset, "no fortran_order True or False in the header");
  // shape "(n,3)": two integers.
  std::size_t n = 0, columns = 0;
  {
    std::vector<std::string> dims;
    std::string d;
    for(char c : shape) {
      if(c == '(' || c == ')') continue;
      if(c == ',') {
        if(!d.empty()) dims.push_back(d);
        d.clear();
      } else {
        d += c;
      }
    }
    if(!d.empty()) dims.push_back(d);
    if(dims.size() != 2 || !parse_integer(std::string_view(dims[0]), n) ||
       !parse_integer(std::string_view(dims[1]), columns) || columns != 3)
      throw in.error_at_offset(header_offset, "unsupported shape " + shape + ", expected (n, 3)");
  }
  const bool little = descr[0] == '<';
  const std::size_t bytes = descr[2] == '8' ? 8 : 4;
  const bool fortran = order == "True";
  std::vector<double> xyz(3 * n);
  const std::size_t values = 3 * n;
  const std::size_t data_offset = in.offset();
  const std::size_t per_block = File_reader::block_size / bytes;
  for(std::size_t j = 0; j < values;) {
    const std::size_t count = std::min(per_block, values - j);
    if(in.available(count * bytes) < count * bytes)
      throw in.error_at_offset(in.offset(), "the file ends after " +
                                                std::to_string((in.offset() - data_offset) / bytes) + " of " +
                                                std::to_string(values) + " values (truncated binary data)");
    const char* p = in.take(count * bytes, "the array");
    for(std::size_t k = 0; k < count; ++k, ++j) {
      // Fortran order stores the columns one after the other.
      const std::size_t target = fortran ? 3 * (j % n) + j / n : j;
      xyz[target] = bytes == 8 ? load<double>(p + 8 * k, little) : double(load<float>(p + 4 * k, little));
    }
  }
  return xyz;
}

// By extension (case-insensitive): .xyz, .ply, .off or .npy.
inline std::vector<double> read_points(const std::string& path, const Read_progress& progress = Read_progress())
{
  const std::string e = point_files::lower_extension(path);
  if(e == "xyz") return read_xyz(path, progress);
  if(e == "ply") return read_ply(path, progress);
  if(e == "off") return read_off(path, progress);
  if(e == "npy") return read_npy(path, progress);
  throw Point_file_error(path + ": unknown point file extension (use .xyz, .ply, .off or .npy)");
}

} // namespace Fast_Delaunay_triangulation_3_io
} // namespace CGAL

#endif // CGAL_FAST_DELAUNAY_TRIANGULATION_3_POINT_CLOUD_IO_H
