// Reading the points of ism_reconstruct's input (.xyz/.pwn, .off, .ply, .las) with messages
// that name the file and the line. CGAL's readers say little about what is wrong, and CGAL
// 5.5's PLY reader crashes on some valid-looking headers, so text files are scanned here
// first; .xyz and .off points are collected by the scan itself.
//
// Errors are thrown as ism_tool::Input_error (a std::runtime_error) whose message is ready to
// print; warnings (the file is read, but something in it looks wrong) are returned, ready to
// print too.

#ifndef ISM_TOOL_READ_POINT_FILE_H
#define ISM_TOOL_READ_POINT_FILE_H

#include <CGAL/IO/read_points.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <sys/stat.h>

namespace ism_tool {

struct Input_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

[[noreturn]] inline void input_error(const std::string& message) { throw Input_error(message); }

// "ply" for "dir/Bunny.PLY"; "" without an extension
inline std::string lowercase_extension(const std::string& filename)
{
  const std::size_t slash = filename.find_last_of('/');
  const std::size_t dot = filename.find_last_of('.');
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = filename.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

namespace internal {

// The number in [b, e), which must be all of it: std::from_chars where it reads the whole
// token (3 times faster than strtod: a third of the dragon's reading time), strtod for the
// rest ('+1', hexadecimal, out of range), so that what is accepted and the values read are
// strtod's. `*e` must not continue a number (a separator or the end of a string).
inline bool parse_number(const char* b, const char* e, double& v)
{
  const std::from_chars_result r = std::from_chars(b, e, v);
  if(r.ec == std::errc() && r.ptr == e) return true;
  char* stop = nullptr;
  v = std::strtod(b, &stop);
  return stop == e && e != b;
}

// a token of OFF or PLY; as strtod reads it, it ends at a NUL byte
inline bool parse_token(const std::string& token, double& v)
{
  return parse_number(token.c_str(), token.c_str() + std::strlen(token.c_str()), v);
}

inline std::vector<std::string> split(const std::string& line)
{
  std::vector<std::string> tokens;
  std::istringstream is(line);
  std::string t;
  while(is >> t) tokens.push_back(t);
  return tokens;
}

// at most `n` characters of `s`, anything but printable ASCII shown as '?'
inline std::string printable(const std::string& s, std::size_t n)
{
  std::string r = s.substr(0, n);
  for(char& c : r)
    if(c < 0x20 || c > 0x7e) c = '?';
  return r + (s.size() > n ? "..." : "");
}

inline std::string where(const std::string& file, std::size_t line) { return "'" + file + "', line " + std::to_string(line); }

// Skips a UTF-8 byte-order mark: Windows editors write one at the start of text files, and
// it says nothing of the format.
inline bool skip_byte_order_mark(std::istream& is)
{
  char b[3];
  if(is.read(b, 3) && std::memcmp(b, "\xEF\xBB\xBF", 3) == 0) return true;
  is.clear();
  is.seekg(0);
  return false;
}

// The whitespace-separated tokens of a text stream across its lines (OFF, and PLY's ASCII
// records); with `comments`, '#' starts a comment to the end of the line (OFF).
class Token_reader
{
public:
  // `lines_read`: the lines of the stream already read (a PLY header)
  Token_reader(std::istream& is, std::size_t lines_read, bool comments)
    : m_is(is), m_line(lines_read), m_comments(comments)
  {}

  // the next token, or "" at the end of the stream
  std::string next()
  {
    while(m_next >= m_tokens.size())
    {
      if(!std::getline(m_is, m_text)) return std::string();
      ++m_line;
      const std::size_t hash = m_comments ? m_text.find('#') : std::string::npos;
      if(hash != std::string::npos) m_text.erase(hash);
      m_tokens = split(m_text);
      m_next = 0;
    }
    return m_tokens[m_next++];
  }

  // the tokens left on the line of the last token (a vertex or face record of OFF is one line)
  std::vector<std::string> rest_of_line()
  {
    std::vector<std::string> r(m_tokens.begin() + std::ptrdiff_t(m_next), m_tokens.end());
    m_next = m_tokens.size();
    return r;
  }

  bool line_is_done() const { return m_next == m_tokens.size(); }

  // the number of the line of the last token
  std::size_t line() const { return m_line; }

private:
  std::istream& m_is;
  std::string m_text;
  std::vector<std::string> m_tokens;
  std::size_t m_next = 0, m_line;
  bool m_comments;
};

// `x y z [nx ny nz ...]` per line, '#' comments, an optional point count on the first line
// (the format of CGAL::IO::read_XYZ); the numbers after x y z are ignored, whatever their
// number (scanners export `x y z intensity`).
// Checks an .xyz/.pwn file line by line (clear messages with line numbers) and, as it
// parses every number anyway, collects the points: a second pass by CGAL's reader cost as
// much again (0.75 s for 437k points in all before, 0.2 s after).
template <class Point>
void scan_xyz(const std::string& file, std::istream& is, std::vector<Point>& out)
{
  std::string line;
  std::size_t number = 0;
  long long announced = -1;
  std::size_t announced_line = 0;
  std::vector<double> values;
  std::size_t tokens = 0;
  while(std::getline(is, line))
  {
    ++number;
    const std::size_t cr = line.find('\r');
    if(cr != std::string::npos && cr + 1 < line.size())
      input_error(where(file, number) + ": a carriage return inside the line (old Mac line endings?); "
                  "convert the file to '\\n' line endings");
    const std::size_t first = line.find_first_not_of(" \t\r");
    if(first == std::string::npos || line[first] == '#') continue;
    // the leading numbers of the line, up to the first token that is not one
    values.clear();
    tokens = 0;
    bool numbers = true;
    const char* c = line.c_str();
    const char* const end = c + line.size();
    while(c < end)
    {
      while(c < end && (*c == ' ' || *c == '\t' || *c == '\r')) ++c;
      if(c == end) break;
      const char* e = c;
      while(e < end && *e != ' ' && *e != '\t' && *e != '\r') ++e;
      ++tokens;
      double v;
      if(numbers && (numbers = parse_number(c, e, v))) values.push_back(v);
      c = e;
    }
    if(number == 1 && tokens == 1 && values.size() == 1 && values[0] >= 0 && values[0] == std::floor(values[0]))
    {
      if(values[0] > 1e15)
        input_error(where(file, number) + " announces " + printable(line, 30) + " points, more than any file holds");
      announced = (long long)values[0];
      announced_line = number;
      continue;
    }
    if(values.size() < 3)
      input_error(where(file, number) + ": expected 'x y z' coordinates, read '" + printable(line, 60) + "'");
    for(int d = 0; d < 3; ++d)
      if(!std::isfinite(values[d]))
        input_error(where(file, number) + ": the point has a NaN or infinite coordinate");
    out.emplace_back(values[0], values[1], values[2]);
  }
  if(is.bad()) input_error("'" + file + "': read error");
  if(out.empty()) input_error("'" + file + "' holds no point");
  if(announced >= 0 && (long long)out.size() != announced)
    input_error(where(file, announced_line) + " announces " + std::to_string(announced) + " points but the file holds " +
                std::to_string(out.size()) + " (truncated?)");
}

// Big-endian 32-bit words of binary OFF
inline bool read_big_endian(std::istream& is, std::uint32_t& w)
{
  unsigned char b[4];
  if(!is.read(reinterpret_cast<char*>(b), 4)) return false;
  w = (std::uint32_t(b[0]) << 24) | (std::uint32_t(b[1]) << 16) | (std::uint32_t(b[2]) << 8) | std::uint32_t(b[3]);
  return true;
}

// OFF in the variants of its definition (Geomview's, which CGAL's reader follows only in
// part): [ST][C][N][4][n]OFF, the counts on the header line or the next, 'BINARY' after the
// keyword; '#' comments. The points are collected here, as CGAL 5.5's reader refuses COFF
// with colours, 4OFF, nOFF, binary OFF and counts on the header line ("malformed or
// truncated"). A vertex's values after its coordinates (normal, colour, texture
// coordinates) are ignored; faces are checked (a truncated file is refused) but not kept.
template <class Point>
void scan_off(const std::string& file, std::istream& is, std::vector<Point>& out, std::vector<std::string>& warnings)
{
  Token_reader in(is, 0, true);
  auto count = [&](const std::string& t, const char* what, double max) {
    double v;
    if(t.empty()) input_error(where(file, in.line()) + ": the file ends before the " + what);
    if(!parse_token(t, v) || v < 0 || v != std::floor(v))
      input_error(where(file, in.line()) + ": expected the " + what + ", read '" + printable(t, 40) + "'");
    if(v > max)
      input_error(where(file, in.line()) + ": '" + printable(t, 40) + "' is too large for the " + what + " (corrupt?)");
    return (unsigned long long)v;
  };

  const std::string header = in.next();
  if(header.empty()) input_error("'" + file + "' holds only white space or comments");
  const std::size_t prefix = header.size() >= 3 ? header.size() - 3 : 0;
  const std::string letters = header.substr(0, prefix);
  if(header.size() < 3 || header.compare(prefix, 3, "OFF") != 0 ||
     letters.find_first_not_of("STCN4n") != std::string::npos)
    input_error(where(file, in.line()) + ": not an OFF file (the first word is '" + printable(header, 40) + "', not 'OFF')");
  const bool homogeneous = letters.find('4') != std::string::npos;
  std::size_t values = homogeneous ? 4 : 3;  // per vertex, in binary: what follows is counted too
  if(letters.find('n') != std::string::npos)
  {
    const unsigned long long dimension = count(in.next(), "dimension of nOFF", 1e6);
    if(dimension != 3)
      input_error(where(file, in.line()) + ": points of dimension " + std::to_string(dimension) + "; only 3D points can be reconstructed");
  }
  std::string t = in.next();
  const bool binary = t == "BINARY";
  if(binary)
  {
    if(!in.line_is_done()) input_error(where(file, in.line()) + ": 'BINARY' must end its line");
    values += (letters.find('N') != std::string::npos ? 3 : 0) + (letters.find('C') != std::string::npos ? 4 : 0) +
              (letters.find("ST") != std::string::npos ? 2 : 0);
  }

  const std::streamoff start = is.tellg();
  is.seekg(0, std::ios::end);
  const unsigned long long size = (unsigned long long)(is.tellg() - start);
  is.seekg(start);
  unsigned long long vertices = 0, faces = 0;
  if(binary)
  {
    std::uint32_t w[3];
    for(std::uint32_t& x : w)
      if(!read_big_endian(is, x)) input_error("'" + file + "': the binary OFF file ends before its counts (truncated?)");
    vertices = w[0];
    faces = w[1];
    if(w[0] > 0x7fffffffu || w[1] > 0x7fffffffu || vertices * values * 4 > size)
      input_error("'" + file + "': the binary OFF file announces " + std::to_string(vertices) +
                  " vertices, more than it holds (truncated or corrupt?)");
  }
  else
  {
    // a vertex count the file cannot hold is refused just below, with the file's size
    vertices = count(t, "vertex and face counts", 1e18);
    faces = count(in.next(), "vertex and face counts", 4e9);
    in.rest_of_line();  // the edge count, ignored as CGAL does
    // at least "0 0 0\n" per vertex (the last without its newline): a count beyond the
    // file is refused before it is reserved
    if(vertices > (size + 1) / 6)
      input_error(where(file, in.line()) + ": announces " + std::to_string(vertices) +
                  " vertices, more than the file can hold (truncated or corrupt?)");
  }
  if(vertices == 0) input_error(where(file, in.line()) + ": the file has no vertex");
  // no more than 16M points ahead: the memory guard of the reconstruction, not the reader,
  // is what refuses a point set too large for the machine
  out.reserve(std::size_t((std::min)(vertices, 1ull << 24)));

  const std::size_t coordinates = homogeneous ? 4 : 3;
  double x[4];
  for(unsigned long long v = 0; v < vertices; ++v)
  {
    if(binary)
    {
      for(std::size_t d = 0; d < values; ++d)
      {
        std::uint32_t w;
        float f;
        read_big_endian(is, w);  // the count check above guarantees the bytes
        std::memcpy(&f, &w, 4);
        if(d < coordinates) x[d] = f;
      }
    }
    else
    {
      t = in.next();
      if(t.empty())
        input_error(where(file, in.line()) + ": the file ends after " + std::to_string(v) + " of " +
                    std::to_string(vertices) + " vertices (truncated?)");
      std::vector<std::string> record(1, t);
      for(const std::string& r : in.rest_of_line()) record.push_back(r);
      if(record.size() < coordinates)
        input_error(where(file, in.line()) + ": vertex " + std::to_string(v) + " has fewer than " +
                    std::to_string(coordinates) + " coordinates");
      for(std::size_t d = 0; d < coordinates; ++d)
        if(!parse_token(record[d], x[d]))
          input_error(where(file, in.line()) + ": vertex " + std::to_string(v) + ": '" + printable(record[d], 40) +
                      "' is not a number");
    }
    // the messages are built only on an error: a string per vertex cost more than the parse
    auto at = [&]() { return binary ? "'" + file + "'" : where(file, in.line()); };
    for(std::size_t d = 0; d < coordinates; ++d)
      if(!std::isfinite(x[d]))
        input_error(at() + ": vertex " + std::to_string(v) + " has a NaN or infinite coordinate");
    if(homogeneous)
    {
      if(x[3] == 0) input_error(at() + ": vertex " + std::to_string(v) + " is at infinity (its 4th coordinate is 0)");
      for(int d = 0; d < 3; ++d) x[d] /= x[3];
      if(!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
        input_error(at() + ": vertex " + std::to_string(v) + " overflows when divided by its 4th coordinate");
    }
    out.emplace_back(x[0], x[1], x[2]);
  }

  // more vertex lines than the header announces (a count not updated after an edit) would be
  // dropped silently: the header decides, as in the format, but the user is told
  if(!binary && faces == 0)
  {
    double v;
    t = in.next();
    if(!t.empty() && parse_token(t, v))
      warnings.push_back(where(file, in.line()) + ": more vertex lines than the " + std::to_string(vertices) +
                         " the header announces (and no face); only the first " + std::to_string(vertices) + " are read");
  }

  for(unsigned long long f = 0; f < faces; ++f)
  {
    auto ends = [&]() { return "the file ends after " + std::to_string(f) + " of " + std::to_string(faces) + " faces (truncated?)"; };
    if(binary)
    {
      // vertex count, indices, colour count, colour components
      auto at = [&]() { return "'" + file + "': face " + std::to_string(f); };
      std::uint32_t k, id, colours;
      if(!read_big_endian(is, k)) input_error("'" + file + "': " + ends());
      if(k == 0 || k > vertices) input_error(at() + " has " + std::to_string(k) + " vertices (corrupt?)");
      for(std::uint32_t j = 0; j < k; ++j)
      {
        if(!read_big_endian(is, id)) input_error("'" + file + "': " + ends());
        if(id >= vertices) input_error(at() + ": " + std::to_string(id) + " is not a vertex index");
      }
      if(!read_big_endian(is, colours)) input_error("'" + file + "': " + ends());
      if(colours > 4) input_error(at() + " has " + std::to_string(colours) + " colour components (corrupt?)");
      for(std::uint32_t j = 0; j < colours; ++j)
        if(!read_big_endian(is, id)) input_error("'" + file + "': " + ends());
      continue;
    }
    t = in.next();
    if(t.empty()) input_error(where(file, in.line()) + ": " + ends());
    double k;
    if(!parse_token(t, k) || k < 1 || k != std::floor(k))
      input_error(where(file, in.line()) + ": face " + std::to_string(f) + ": expected a vertex count, read '" +
                  printable(t, 40) + "'" +
                  // a coordinate where the first face should be: the vertex count is too small
                  (f == 0 && parse_token(t, k) ? " (more vertices than the " + std::to_string(vertices) + " the header announces?)" : ""));
    const std::vector<std::string> record = in.rest_of_line();
    if(record.size() < std::size_t(k))
      input_error(where(file, in.line()) + ": face " + std::to_string(f) + " lists fewer than " +
                  std::to_string(long(k)) + " vertices (truncated?)");
    for(std::size_t j = 0; j < std::size_t(k); ++j)
    {
      double id;
      if(!parse_token(record[j], id) || id < 0 || id >= double(vertices) || id != std::floor(id))
        input_error(where(file, in.line()) + ": face " + std::to_string(f) + ": '" + printable(record[j], 40) +
                    "' is not a vertex index");
    }
  }
}

// PLY: the header, then every element's records, without keeping them. CGAL 5.5's reader
// dereferences a null pointer on coordinates stored as integers or lists and on a property
// before any element, silently drops a property of unknown type (misreading the rest), and
// allocates whatever a list count says (a 117-byte file with a count of 4e9 took 3.9 GB
// and 56 s before failing): each is refused here with its line.
inline void scan_ply(const std::string& file, std::istream& is, std::vector<std::string>& warnings)
{
  struct Property
  {
    std::string name;
    int size = 0;        // bytes of a scalar, or of a list's items
    int count_size = 0;  // bytes of a list's count; 0 for a scalar
    bool real = false;   // a scalar float or double
  };
  struct Element
  {
    std::string name;
    unsigned long long count = 0;
    std::vector<Property> properties;
  };
  auto type_size = [](const std::string& t) {
    if(t == "char" || t == "int8" || t == "uchar" || t == "uint8") return 1;
    if(t == "short" || t == "int16" || t == "ushort" || t == "uint16") return 2;
    if(t == "int" || t == "int32" || t == "uint" || t == "uint32" || t == "float" || t == "float32") return 4;
    if(t == "double" || t == "float64") return 8;
    return 0;
  };
  auto is_real = [](const std::string& t) { return t == "float" || t == "float32" || t == "double" || t == "float64"; };

  std::string line;
  std::size_t number = 0;
  std::vector<Element> elements;
  bool ascii = false, big_endian = false, ended = false;
  while(!ended && std::getline(is, line))
  {
    ++number;
    const std::vector<std::string> t = split(line);
    if(number == 1)
    {
      if(t.size() != 1 || t[0] != "ply") input_error(where(file, number) + ": not a PLY file (it does not start with 'ply')");
      continue;
    }
    if(t.empty()) input_error(where(file, number) + ": empty line in the PLY header");
    if(number == 2)
    {
      if(t.size() != 3 || t[0] != "format" ||
         (t[1] != "ascii" && t[1] != "binary_little_endian" && t[1] != "binary_big_endian"))
        input_error(where(file, number) + ": expected 'format ascii|binary_little_endian|binary_big_endian 1.0', read '" +
                    printable(line, 60) + "'");
      ascii = t[1] == "ascii";
      big_endian = t[1] == "binary_big_endian";
    }
    else if(t[0] == "comment" || t[0] == "obj_info") {}
    else if(t[0] == "end_header") ended = true;
    else if(t[0] == "element")
    {
      double count;
      if(t.size() != 3 || !parse_token(t[2], count) || count < 0 || count != std::floor(count))
        input_error(where(file, number) + ": expected 'element NAME COUNT', read '" + printable(line, 60) + "'");
      if(count > 1e15)
        input_error(where(file, number) + ": the element '" + printable(t[1], 20) + "' announces " + printable(t[2], 30) +
                    " records, more than any file holds (corrupt?)");
      elements.push_back(Element{t[1], (unsigned long long)count, {}});
    }
    else if(t[0] == "property")
    {
      if(elements.empty()) input_error(where(file, number) + ": a property before any element");
      Property p;
      const bool list = t.size() == 5 && t[1] == "list";
      if(!list && t.size() != 3)
        input_error(where(file, number) + ": expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME', read '" +
                    printable(line, 60) + "'");
      p.name = t.back();
      p.size = type_size(t[list ? 3 : 1]);
      if(p.size == 0) input_error(where(file, number) + ": unknown property type '" + printable(t[list ? 3 : 1], 20) + "'");
      if(list)
      {
        p.count_size = type_size(t[2]);
        if(p.count_size == 0 || is_real(t[2]))
          input_error(where(file, number) + ": a list's count must have an integer type, not '" + printable(t[2], 20) + "'");
      }
      p.real = !list && is_real(t[1]);
      elements.back().properties.push_back(p);
    }
    else
      input_error(where(file, number) + ": unknown keyword '" + printable(t[0], 20) + "' in the PLY header");
  }
  if(!ended) input_error("'" + file + "': the PLY header has no 'end_header' line (truncated?)");

  const Element* vertex = nullptr;
  for(const Element& e : elements)
    if(e.name == "vertex") vertex = &e;
  if(vertex == nullptr || vertex->count == 0) input_error("'" + file + "' holds no point (no vertex element, or 0 vertices)");
  for(const char* c : {"x", "y", "z"})
  {
    auto p = std::find_if(vertex->properties.begin(), vertex->properties.end(), [&](const Property& q) { return q.name == c; });
    if(p == vertex->properties.end()) input_error("'" + file + "': the vertex element has no property '" + c + "'");
    if(!p->real)
      input_error("'" + file + "': the vertex property '" + c + "' is " + (p->count_size ? "a list" : "an integer") +
                  "; CGAL's PLY reader takes coordinates as float or double");
  }

  // the records: a count beyond what is left of the file is refused before any reader trusts it
  const std::string truncated = "'" + file + "': the file ends inside the PLY element '";
  if(ascii)
  {
    Token_reader in(is, number, false);
    auto token = [&](std::string& out) { return !(out = in.next()).empty(); };
    std::string t;
    double v;
    for(const Element& e : elements)
    {
      auto ends = [&](unsigned long long r) {
        input_error(truncated + printable(e.name, 20) + "' (record " + std::to_string(r) + " of " + std::to_string(e.count) + ")");
      };
      for(unsigned long long r = 0; r < e.count; ++r)
        for(const Property& p : e.properties)
        {
          unsigned long long items = 1;
          if(p.count_size)
          {
            if(!token(t)) ends(r);
            if(!parse_token(t, v) || v < 0 || v != std::floor(v))
              input_error(where(file, in.line()) + ": '" + printable(t, 40) + "' is not a list count");
            items = (unsigned long long)v;
          }
          for(unsigned long long i = 0; i < items; ++i)
          {
            if(!token(t)) ends(r);
            if(!parse_token(t, v)) input_error(where(file, in.line()) + ": '" + printable(t, 40) + "' is not a number");
            // CGAL's reader fails on them without saying where
            if(!std::isfinite(v))
            {
              if(e.name == "vertex" && (p.name == "x" || p.name == "y" || p.name == "z"))
                input_error(where(file, in.line()) + ": vertex " + std::to_string(r) + " has a NaN or infinite coordinate");
              input_error(where(file, in.line()) + ": the property '" + printable(p.name, 20) + "' of the element '" +
                          printable(e.name, 20) + "' (record " + std::to_string(r) +
                          ") is NaN or infinite, which CGAL's PLY reader cannot read");
            }
          }
        }
    }
    // more records than the header announces (a count not updated after an edit) would be
    // dropped silently: the header decides, as in the format, but the user is told
    if(token(t))
      warnings.push_back(where(file, in.line()) + ": more data than the header announces (after the " +
                         std::to_string(elements.back().count) + " records of the element '" +
                         printable(elements.back().name, 20) + "'); it is ignored");
    return;
  }
  const std::streamoff data = is.tellg();
  is.seekg(0, std::ios::end);
  const std::streamoff end = is.tellg();
  is.seekg(data);
  unsigned long long left = (unsigned long long)(end - data);
  for(const Element& e : elements)
  {
    unsigned long long record = 0;
    bool lists = false;
    for(const Property& p : e.properties)
    {
      record += unsigned(p.count_size ? p.count_size : p.size);
      lists = lists || p.count_size;
    }
    if(!lists)
    {
      if(record != 0 && e.count > left / record) input_error(truncated + printable(e.name, 20) + "' (truncated?)");
      left -= e.count * record;
      is.seekg(std::streamoff(e.count * record), std::ios::cur);
      continue;
    }
    for(unsigned long long r = 0; r < e.count; ++r)
      for(const Property& p : e.properties)
      {
        if(left < unsigned(p.count_size ? p.count_size : p.size))
          input_error(truncated + printable(e.name, 20) + "' (record " + std::to_string(r) + ", truncated?)");
        if(!p.count_size)
        {
          left -= unsigned(p.size);
          is.seekg(p.size, std::ios::cur);
          continue;
        }
        unsigned char b[4] = {0, 0, 0, 0};
        is.read(reinterpret_cast<char*>(b), p.count_size);
        left -= unsigned(p.count_size);
        unsigned long long items = 0;
        for(int k = 0; k < p.count_size; ++k)
          items |= (unsigned long long)b[big_endian ? p.count_size - 1 - k : k] << (8 * k);
        if(items > left / unsigned(p.size))
          input_error(truncated + printable(e.name, 20) + "': record " + std::to_string(r) + " lists " +
                      std::to_string(items) + " items (truncated or corrupt?)");
        left -= items * unsigned(p.size);
        is.seekg(std::streamoff(items * unsigned(p.size)), std::ios::cur);
      }
  }
}

} // namespace internal

// The points of `file`; throws Input_error with a message naming the file (and the line
// where it can) if the file cannot be read, is empty, malformed or truncated, holds no
// point or a NaN or infinite coordinate. `warnings` receives what is read but looks wrong.
template <class Point>
std::vector<Point> read_point_file(const std::string& file, std::vector<std::string>& warnings)
{
  using namespace internal;
  struct stat st;
  if(::stat(file.c_str(), &st) != 0)
    input_error("cannot open '" + file + "': " + std::strerror(errno));
  if(S_ISDIR(st.st_mode)) input_error("cannot read '" + file + "': it is a directory");
  // a pipe would block on open without a writer, and the scan below and CGAL's reader each
  // open the file: a second open of a pipe waits for a writer that has gone
  if(!S_ISREG(st.st_mode))
    input_error("cannot read '" + file + "': not a regular file (a pipe or a device); write the points to a file first");
  std::ifstream probe(file, std::ios::binary);
  if(!probe) input_error("cannot open '" + file + "': " + std::strerror(errno));
  if(probe.peek() == std::ifstream::traits_type::eof()) input_error("'" + file + "' is empty");
  const bool byte_order_mark = skip_byte_order_mark(probe);

  const std::string ext = lowercase_extension(file);
  std::vector<Point> points;
  if(ext == "xyz" || ext == "pwn")
  {
    scan_xyz(file, probe, points);
    return points;
  }
  else if(ext == "off")
  {
    scan_off(file, probe, points, warnings);
    return points;
  }
  else if(ext == "ply") scan_ply(file, probe, warnings);
#ifdef CGAL_LINKED_WITH_LASLIB
  else if(ext == "las") {}
#else
  else if(ext == "las")
    input_error("cannot read '" + file + "': this build of CGAL is not linked with LASlib (no .las support)");
#endif
  else
    input_error("cannot read '" + file + "': " + (ext.empty() ? std::string("no extension to tell its format") : "unknown format '." + ext + "'") +
                " (use .xyz, .pwn, .ply or .off)");

  bool ok;
  {
    // CGAL's readers print their own diagnostics on std::cerr; ours are clearer
    std::ostringstream silenced;
    std::streambuf* old = std::cerr.rdbuf(silenced.rdbuf());
    try
    {
      if(ext == "ply")
      {
        // from past a byte-order mark, which CGAL's reader (given the name) would not skip
        probe.clear();
        probe.seekg(byte_order_mark ? 3 : 0);
        CGAL::IO::set_mode(probe, CGAL::IO::BINARY);
        ok = CGAL::IO::read_PLY(probe, std::back_inserter(points));
      }
      else
        ok = CGAL::IO::read_points(file, std::back_inserter(points));
    }
    catch(...) { ok = false; }
    std::cerr.rdbuf(old);
  }
  probe.close();
  if(!ok) input_error("cannot read points from '" + file + "': the file is malformed or truncated");
  if(points.empty()) input_error("'" + file + "' holds no point");
  for(std::size_t i = 0; i < points.size(); ++i)
    if(!std::isfinite(points[i].x()) || !std::isfinite(points[i].y()) || !std::isfinite(points[i].z()))
      input_error("'" + file + "': point " + std::to_string(i) + " has a NaN or infinite coordinate");
  return points;
}

} // namespace ism_tool

#endif // ISM_TOOL_READ_POINT_FILE_H
