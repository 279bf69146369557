// Copyright (c) 2026 ISM_reconstruction_3 developers.
// This file is part of CGAL (www.cgal.org).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : ISM_reconstruction_3 developers

#ifndef CGAL_ISM_RECONSTRUCTION_3_IO_TET_MESH_IO_H
#define CGAL_ISM_RECONSTRUCTION_3_IO_TET_MESH_IO_H

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <ostream>
#include <iterator>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace IO {

/*!
\ingroup PkgISMReconstruction3IO

A named scalar field with one value per vertex of a tetrahedral mesh, for example
`{"sign", values}`. `second.size()` must be the number of points of the mesh.
*/
using Tet_mesh_vertex_field = std::pair<std::string, std::vector<double> >;

} // namespace IO

namespace ISM_reconstruction_3 {
namespace internal {
namespace tet_mesh_io {

// Formatting goes through a private buffer and std::to_chars rather than `os << x`:
// for ~10 M tetrahedra the per-call sentry and locale work of operator<< dominates,
// and file formats must not depend on the stream's imbued locale anyway.
class Text_writer
{
public:
  explicit Text_writer(std::ostream& os) : m_os(os), m_buf(1 << 16), m_n(0) {}
  Text_writer(const Text_writer&) = delete;
  Text_writer& operator=(const Text_writer&) = delete;
  // No flush in the destructor: callers flush explicitly on success, and on failure
  // the rest is useless (and writing it from a destructor could throw).

  void put(char c)
  {
    reserve(1);
    m_buf[m_n++] = c;
  }

  void put(const char* s)
  {
    put(s, std::strlen(s));
  }

  void put(const std::string& s)
  {
    put(s.data(), s.size());
  }

  void put(const char* s, std::size_t len)
  {
    if(len > m_buf.size()) { // too long to be worth buffering
      flush();
      m_os.write(s, static_cast<std::streamsize>(len));
      return;
    }
    reserve(len);
    std::memcpy(m_buf.data() + m_n, s, len);
    m_n += len;
  }

  template <class Integer>
  void put_integer(Integer v)
  {
    static_assert(std::is_integral<Integer>::value, "integer expected");
    reserve(24);
    std::to_chars_result r = std::to_chars(m_buf.data() + m_n, m_buf.data() + m_buf.size(), v);
    m_n = static_cast<std::size_t>(r.ptr - m_buf.data());
  }

  // Same digits as `os << std::setprecision(17) << v`, i.e. `%.17g`: enough to round-trip.
  void put_double(double v)
  {
    reserve(32);
#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
    std::to_chars_result r = std::to_chars(m_buf.data() + m_n, m_buf.data() + m_buf.size(),
                                           v, std::chars_format::general, 17);
    m_n = static_cast<std::size_t>(r.ptr - m_buf.data());
#else
    // Standard libraries without floating-point to_chars: snprintf uses the C locale
    // unless the program called setlocale(), which is the usual case.
    int k = std::snprintf(m_buf.data() + m_n, 32, "%.17g", v);
    if(k > 0)
      m_n += static_cast<std::size_t>(k);
#endif
  }

  bool flush()
  {
    if(m_n > 0) {
      m_os.write(m_buf.data(), static_cast<std::streamsize>(m_n));
      m_n = 0;
    }
    return !m_os.fail();
  }

private:
  void reserve(std::size_t k)
  {
    if(m_n + k > m_buf.size())
      flush();
  }

  std::ostream& m_os;
  std::vector<char> m_buf;
  std::size_t m_n;
};

// Streams raw bytes as base64 without materializing the whole array: one VTU
// DataArray of 10 M tetrahedra is hundreds of MB.
class Base64_writer
{
public:
  explicit Base64_writer(std::ostream& os)
    : m_os(os), m_in(3 * 8192), m_out(4 * 8192), m_nin(0)
  {}
  Base64_writer(const Base64_writer&) = delete;
  Base64_writer& operator=(const Base64_writer&) = delete;

  template <class T>
  void put(const T& v)
  {
    static_assert(std::is_trivially_copyable<T>::value, "raw bytes expected");
    if(m_nin + sizeof(T) > m_in.size())
      encode_complete_triples();
    std::memcpy(m_in.data() + m_nin, &v, sizeof(T));
    m_nin += sizeof(T);
  }

  // Ends the current base64 stream (with padding); the writer can then start another one.
  bool finish()
  {
    encode_complete_triples();
    if(m_nin > 0) {
      const unsigned char* p = m_in.data();
      char out[4];
      const unsigned int b0 = p[0];
      const unsigned int b1 = (m_nin > 1) ? p[1] : 0u;
      out[0] = alphabet()[b0 >> 2];
      out[1] = alphabet()[((b0 & 0x3u) << 4) | (b1 >> 4)];
      out[2] = (m_nin > 1) ? alphabet()[(b1 & 0xFu) << 2] : '=';
      out[3] = '=';
      m_os.write(out, 4);
      m_nin = 0;
    }
    return !m_os.fail();
  }

private:
  static const char* alphabet()
  {
    return "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  }

  void encode_complete_triples()
  {
    const std::size_t n3 = (m_nin / 3) * 3;
    const unsigned char* p = m_in.data();
    char* q = m_out.data();
    const char* a = alphabet();
    for(std::size_t i = 0; i < n3; i += 3, q += 4) {
      const std::uint32_t w = (std::uint32_t(p[i]) << 16) | (std::uint32_t(p[i + 1]) << 8) | p[i + 2];
      q[0] = a[(w >> 18) & 0x3F];
      q[1] = a[(w >> 12) & 0x3F];
      q[2] = a[(w >> 6) & 0x3F];
      q[3] = a[w & 0x3F];
    }
    if(n3 > 0)
      m_os.write(m_out.data(), static_cast<std::streamsize>(q - m_out.data()));
    // keep the 0 to 2 leftover bytes for the next triple
    const std::size_t rest = m_nin - n3;
    for(std::size_t i = 0; i < rest; ++i)
      m_in[i] = m_in[n3 + i];
    m_nin = rest;
  }

  std::ostream& m_os;
  std::vector<unsigned char> m_in;
  std::vector<char> m_out;
  std::size_t m_nin;
};

template <class Integer>
bool is_valid_index(const Integer& i, std::size_t nb_points)
{
  static_assert(std::is_integral<Integer>::value,
                "the tetrahedra must be arrays of 4 integer indices");
  if constexpr(std::is_signed<Integer>::value) {
    if(i < 0)
      return false;
  }
  return static_cast<unsigned long long>(i) < static_cast<unsigned long long>(nb_points);
}

template <class Range>
std::size_t range_size(const Range& r)
{
  return static_cast<std::size_t>(std::distance(std::begin(r), std::end(r)));
}

// All writers validate before writing anything, so bad input never yields a
// half-written file that looks complete, nor an out-of-range access.
template <class TetRange>
bool check_tets(const TetRange& tets, std::size_t nb_points, std::size_t& nb_tets)
{
  nb_tets = 0;
  for(const auto& t : tets) {
    for(std::size_t k = 0; k < 4; ++k)
      if(!is_valid_index(t[k], nb_points))
        return false;
    ++nb_tets;
  }
  return true;
}

inline bool check_fields(const std::vector<CGAL::IO::Tet_mesh_vertex_field>& fields,
                         std::size_t nb_points)
{
  for(const CGAL::IO::Tet_mesh_vertex_field& f : fields)
    if(f.second.size() != nb_points)
      return false;
  return true;
}

template <class Point>
std::array<double, 3> to_double_array(const Point& p)
{
  return {{ CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) }};
}

inline bool is_little_endian()
{
  const std::uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

// Field names come from users and end up in an XML attribute.
inline void put_xml_escaped(Text_writer& w, const std::string& s)
{
  for(char c : s) {
    switch(c) {
      case '&': w.put("&amp;"); break;
      case '<': w.put("&lt;"); break;
      case '>': w.put("&gt;"); break;
      case '"': w.put("&quot;"); break;
      case '\'': w.put("&apos;"); break;
      default: w.put(c);
    }
  }
}

// Writes one DataArray body; `Value` is the on-disk type and `for_each_value(sink)`
// calls `sink(v)` for every value in file order, so the caller never builds the array.
template <class Value, class ForEach>
bool write_vtu_data_array(std::ostream& os, Text_writer& w, bool binary,
                          std::size_t nb_values, int values_per_line, const ForEach& for_each_value)
{
  if(binary) {
    if(!w.flush())
      return false;
    Base64_writer b(os);
    // Uncompressed inline binary: the UInt64 byte count and the data form one base64 stream.
    b.put(static_cast<std::uint64_t>(nb_values * sizeof(Value)));
    for_each_value([&b](Value v) { b.put(v); });
    if(!b.finish())
      return false;
    w.put('\n');
  } else {
    int col = 0;
    for_each_value([&](Value v) {
      if constexpr(std::is_floating_point<Value>::value)
        w.put_double(static_cast<double>(v));
      else // widen so that uint8 is not written as a character
        w.put_integer(static_cast<long long>(v));
      if(++col == values_per_line) {
        w.put('\n');
        col = 0;
      } else {
        w.put(' ');
      }
    });
    if(col != 0)
      w.put('\n');
  }
  return true;
}

template <class Integer, class TetRange>
bool write_vtu_cells(std::ostream& os, Text_writer& w, bool binary,
                     const TetRange& tets, std::size_t nb_tets, const char* format)
{
  w.put("        <DataArray type=\"");
  w.put(std::is_same<Integer, std::int32_t>::value ? "Int32" : "Int64");
  w.put("\" Name=\"connectivity\" format=\"");
  w.put(format);
  w.put("\">\n");
  if(!write_vtu_data_array<Integer>(os, w, binary, 4 * nb_tets, 4, [&tets](auto&& sink) {
       for(const auto& t : tets)
         for(std::size_t k = 0; k < 4; ++k)
           sink(static_cast<Integer>(t[k]));
     }))
    return false;
  w.put("        </DataArray>\n");

  w.put("        <DataArray type=\"");
  w.put(std::is_same<Integer, std::int32_t>::value ? "Int32" : "Int64");
  w.put("\" Name=\"offsets\" format=\"");
  w.put(format);
  w.put("\">\n");
  if(!write_vtu_data_array<Integer>(os, w, binary, nb_tets, 8, [nb_tets](auto&& sink) {
       for(std::size_t i = 1; i <= nb_tets; ++i)
         sink(static_cast<Integer>(4 * i));
     }))
    return false;
  w.put("        </DataArray>\n");
  return true;
}

} // namespace tet_mesh_io
} // namespace internal
} // namespace ISM_reconstruction_3

namespace IO {

/*!
\ingroup PkgISMReconstruction3IO

\brief writes a tetrahedral mesh and per-vertex scalar fields in the VTK XML
`UnstructuredGrid` format (`.vtu`), readable by ParaView and `vtkXMLUnstructuredGridReader`.

Points are written as `Float64`, cells as `VTK_TETRA` (10), each field as a `Float64`
point-data array named after the field; the first field is marked as the active scalars.
Connectivity and offsets are `Int32` when they fit, `Int64` otherwise, which halves the
file size of typical meshes.

\tparam PointRange a model of `ConstRange` whose value type is a `Point_3` of any kernel.
\tparam TetRange a model of `ConstRange` whose value type is `std::array<I, 4>` for an
        integer type `I`; indices are 0-based into `points`.

\param os the output stream
\param points the vertices of the mesh
\param tets the tetrahedra; they are written as given, so a positively oriented input
       gives positive volumes in VTK
\param fields per-vertex scalar fields
\param binary if `true`, arrays are written inline, base64-encoded, with a `UInt64` header
       (`header_type="UInt64"`), in the byte order of the machine; otherwise as ASCII text
       with 17 significant digits

\return `false` if an index is out of range, a field does not have one value per point,
        or writing to `os` failed; nothing is written in the first two cases.
*/
template <class PointRange, class TetRange>
bool write_tet_mesh_VTU(std::ostream& os,
                        const PointRange& points,
                        const TetRange& tets,
                        const std::vector<Tet_mesh_vertex_field>& fields = {},
                        bool binary = true)
{
  namespace tmi = ISM_reconstruction_3::internal::tet_mesh_io;

  const std::size_t nb_points = tmi::range_size(points);
  std::size_t nb_tets = 0;
  if(!os || !tmi::check_tets(tets, nb_points, nb_tets) || !tmi::check_fields(fields, nb_points))
    return false;

  const char* format = binary ? "binary" : "ascii";
  tmi::Text_writer w(os);

  w.put("<?xml version=\"1.0\"?>\n"
        "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"");
  w.put(tmi::is_little_endian() ? "LittleEndian" : "BigEndian");
  w.put("\" header_type=\"UInt64\">\n"
        "  <UnstructuredGrid>\n"
        "    <Piece NumberOfPoints=\"");
  w.put_integer(nb_points);
  w.put("\" NumberOfCells=\"");
  w.put_integer(nb_tets);
  w.put("\">\n");

  if(!fields.empty()) {
    w.put("      <PointData Scalars=\"");
    tmi::put_xml_escaped(w, fields.front().first);
    w.put("\">\n");
    for(const Tet_mesh_vertex_field& f : fields) {
      w.put("        <DataArray type=\"Float64\" Name=\"");
      tmi::put_xml_escaped(w, f.first);
      w.put("\" format=\"");
      w.put(format);
      w.put("\">\n");
      if(!tmi::write_vtu_data_array<double>(os, w, binary, nb_points, 6, [&f](auto&& sink) {
           for(double v : f.second)
             sink(v);
         }))
        return false;
      w.put("        </DataArray>\n");
    }
    w.put("      </PointData>\n");
  }

  w.put("      <Points>\n"
        "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"");
  w.put(format);
  w.put("\">\n");
  if(!tmi::write_vtu_data_array<double>(os, w, binary, 3 * nb_points, 3, [&points](auto&& sink) {
       for(const auto& p : points) {
         const std::array<double, 3> c = tmi::to_double_array(p);
         sink(c[0]);
         sink(c[1]);
         sink(c[2]);
       }
     }))
    return false;
  w.put("        </DataArray>\n"
        "      </Points>\n"
        "      <Cells>\n");

  // The largest value stored is the last offset, 4 * nb_tets (indices are < nb_points).
  const std::size_t int32_max = static_cast<std::size_t>((std::numeric_limits<std::int32_t>::max)());
  const bool fits_int32 = nb_points <= int32_max && nb_tets <= int32_max / 4;
  const bool cells_ok = fits_int32
    ? tmi::write_vtu_cells<std::int32_t>(os, w, binary, tets, nb_tets, format)
    : tmi::write_vtu_cells<std::int64_t>(os, w, binary, tets, nb_tets, format);
  if(!cells_ok)
    return false;

  w.put("        <DataArray type=\"UInt8\" Name=\"types\" format=\"");
  w.put(format);
  w.put("\">\n");
  if(!tmi::write_vtu_data_array<std::uint8_t>(os, w, binary, nb_tets, 16, [nb_tets](auto&& sink) {
       const std::uint8_t vtk_tetra = 10;
       for(std::size_t i = 0; i < nb_tets; ++i)
         sink(vtk_tetra);
     }))
    return false;
  w.put("        </DataArray>\n"
        "      </Cells>\n"
        "    </Piece>\n"
        "  </UnstructuredGrid>\n"
        "</VTKFile>\n");
  return w.flush();
}

/*!
\ingroup PkgISMReconstruction3IO

\brief writes a tetrahedral mesh in the ASCII Medit format (`.mesh`), keywords
`Vertices` and `Tetrahedra`, with 1-based indices as the format requires.

The file is `MeshVersionFormatted 2` (double precision) and coordinates have 17
significant digits. Vertex references are `0` and tetrahedron references `1`, a
single subdomain. Per-vertex fields go to a companion `.sol` file,
see `write_tet_mesh_MEDIT_sol()`.

\tparam PointRange a model of `ConstRange` whose value type is a `Point_3` of any kernel.
\tparam TetRange a model of `ConstRange` whose value type is `std::array<I, 4>` for an
        integer type `I`; indices are 0-based into `points`.

\return `false` if an index is out of range (nothing is written) or writing to `os` failed.
*/
template <class PointRange, class TetRange>
bool write_tet_mesh_MEDIT(std::ostream& os,
                          const PointRange& points,
                          const TetRange& tets)
{
  namespace tmi = ISM_reconstruction_3::internal::tet_mesh_io;

  const std::size_t nb_points = tmi::range_size(points);
  std::size_t nb_tets = 0;
  if(!os || !tmi::check_tets(tets, nb_points, nb_tets))
    return false;

  tmi::Text_writer w(os);
  w.put("MeshVersionFormatted 2\n"
        "Dimension 3\n"
        "Vertices\n");
  w.put_integer(nb_points);
  w.put('\n');
  for(const auto& p : points) {
    const std::array<double, 3> c = tmi::to_double_array(p);
    w.put_double(c[0]);
    w.put(' ');
    w.put_double(c[1]);
    w.put(' ');
    w.put_double(c[2]);
    w.put(" 0\n");
  }
  w.put("Tetrahedra\n");
  w.put_integer(nb_tets);
  w.put('\n');
  for(const auto& t : tets) {
    for(std::size_t k = 0; k < 4; ++k) {
      w.put_integer(static_cast<unsigned long long>(t[k]) + 1);
      w.put(' ');
    }
    w.put("1\n");
  }
  w.put("End\n");
  return w.flush();
}

/*!
\ingroup PkgISMReconstruction3IO

\brief writes per-vertex scalar fields as an ASCII Medit solution file (`.sol`),
the companion of a `.mesh` file written by `write_tet_mesh_MEDIT()`.

The file holds one `SolAtVertices` block with one scalar solution (type `1`) per field,
in the order of `fields`; the format has no room for the field names.

\param os the output stream
\param nb_points the number of vertices of the mesh
\param fields the fields, each with `nb_points` values

\return `false` if `fields` is empty or a field does not have `nb_points` values
        (nothing is written), or if writing to `os` failed.
*/
inline bool write_tet_mesh_MEDIT_sol(std::ostream& os,
                                     std::size_t nb_points,
                                     const std::vector<Tet_mesh_vertex_field>& fields)
{
  namespace tmi = ISM_reconstruction_3::internal::tet_mesh_io;

  if(!os || fields.empty() || !tmi::check_fields(fields, nb_points))
    return false;

  tmi::Text_writer w(os);
  w.put("MeshVersionFormatted 2\n"
        "Dimension 3\n"
        "SolAtVertices\n");
  w.put_integer(nb_points);
  w.put('\n');
  w.put_integer(fields.size());
  for(std::size_t j = 0; j < fields.size(); ++j)
    w.put(" 1");
  w.put('\n');
  for(std::size_t i = 0; i < nb_points; ++i) {
    for(std::size_t j = 0; j < fields.size(); ++j) {
      if(j > 0)
        w.put(' ');
      w.put_double(fields[j].second[i]);
    }
    w.put('\n');
  }
  w.put("End\n");
  return w.flush();
}

/*!
\ingroup PkgISMReconstruction3IO

\brief writes a tetrahedral mesh in the TetGen format, as a `.node` and an `.ele` stream.

Indices are 0-based (TetGen detects the base from the first node). The fields become
node attributes, in the order of `fields`; their names are listed in a leading `#`
comment of the `.node` stream, since the format itself has no names. There are no
boundary markers nor region attributes.

\tparam PointRange a model of `ConstRange` whose value type is a `Point_3` of any kernel.
\tparam TetRange a model of `ConstRange` whose value type is `std::array<I, 4>` for an
        integer type `I`; indices are 0-based into `points`.

\return `false` if an index is out of range or a field does not have one value per point
        (nothing is written), or if writing to either stream failed.
*/
template <class PointRange, class TetRange>
bool write_tet_mesh_TetGen(std::ostream& node_os,
                           std::ostream& ele_os,
                           const PointRange& points,
                           const TetRange& tets,
                           const std::vector<Tet_mesh_vertex_field>& fields = {})
{
  namespace tmi = ISM_reconstruction_3::internal::tet_mesh_io;

  const std::size_t nb_points = tmi::range_size(points);
  std::size_t nb_tets = 0;
  if(!node_os || !ele_os || !tmi::check_tets(tets, nb_points, nb_tets) ||
     !tmi::check_fields(fields, nb_points))
    return false;

  {
    tmi::Text_writer w(node_os);
    if(!fields.empty()) {
      w.put("# attributes:");
      for(const Tet_mesh_vertex_field& f : fields) {
        w.put(' ');
        // a line break in a name would end the comment early
        for(char c : f.first)
          w.put((c == '\n' || c == '\r') ? ' ' : c);
      }
      w.put('\n');
    }
    w.put_integer(nb_points);
    w.put(" 3 ");
    w.put_integer(fields.size());
    w.put(" 0\n");
    std::size_t i = 0;
    for(const auto& p : points) {
      const std::array<double, 3> c = tmi::to_double_array(p);
      w.put_integer(i);
      for(std::size_t k = 0; k < 3; ++k) {
        w.put(' ');
        w.put_double(c[k]);
      }
      for(const Tet_mesh_vertex_field& f : fields) {
        w.put(' ');
        w.put_double(f.second[i]);
      }
      w.put('\n');
      ++i;
    }
    if(!w.flush())
      return false;
  }

  tmi::Text_writer w(ele_os);
  w.put_integer(nb_tets);
  w.put(" 4 0\n");
  std::size_t i = 0;
  for(const auto& t : tets) {
    w.put_integer(i++);
    for(std::size_t k = 0; k < 4; ++k) {
      w.put(' ');
      w.put_integer(static_cast<unsigned long long>(t[k]));
    }
    w.put('\n');
  }
  return w.flush();
}

/*!
\ingroup PkgISMReconstruction3IO

\brief writes a tetrahedral mesh and per-vertex fields, the format being chosen from the
extension of `filename` (case-insensitive).

- `.vtu`: `write_tet_mesh_VTU()`, binary;
- `.mesh`: `write_tet_mesh_MEDIT()`, plus `<basename>.sol` by `write_tet_mesh_MEDIT_sol()`
  when `fields` is not empty;
- `.node` or `.ele`: `write_tet_mesh_TetGen()` into `<basename>.node` and `<basename>.ele`.

\tparam PointRange a model of `ConstRange` whose value type is a `Point_3` of any kernel.
\tparam TetRange a model of `ConstRange` whose value type is `std::array<I, 4>` for an
        integer type `I`; indices are 0-based into `points`.

\return `false` if the extension is not one of the above, the input is invalid, or a
        file could not be opened or written.
*/
template <class PointRange, class TetRange>
bool write_tet_mesh(const std::string& filename,
                    const PointRange& points,
                    const TetRange& tets,
                    const std::vector<Tet_mesh_vertex_field>& fields = {})
{
  namespace tmi = ISM_reconstruction_3::internal::tet_mesh_io;

  // only the last component may carry the extension ("dir.v1/mesh" has none)
  const std::size_t slash = filename.find_last_of("/\\");
  const std::size_t dot = filename.find_last_of('.');
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return false;
  const std::string basename = filename.substr(0, dot);
  std::string ext = filename.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });

  // Validate first, so that no file is created or truncated for bad input.
  const std::size_t nb_points = tmi::range_size(points);
  std::size_t nb_tets = 0;
  if(!tmi::check_tets(tets, nb_points, nb_tets) || !tmi::check_fields(fields, nb_points))
    return false;

  // Binary mode everywhere: '\n' line ends on every platform and base64 untouched.
  if(ext == ".vtu") {
    std::ofstream os(filename, std::ios::binary);
    return write_tet_mesh_VTU(os, points, tets, fields, true) && os.flush();
  }
  if(ext == ".mesh") {
    std::ofstream os(filename, std::ios::binary);
    if(!write_tet_mesh_MEDIT(os, points, tets) || !os.flush())
      return false;
    if(fields.empty())
      return true;
    std::ofstream sol_os(basename + ".sol", std::ios::binary);
    return write_tet_mesh_MEDIT_sol(sol_os, nb_points, fields) && sol_os.flush();
  }
  if(ext == ".node" || ext == ".ele") {
    std::ofstream node_os(basename + ".node", std::ios::binary);
    std::ofstream ele_os(basename + ".ele", std::ios::binary);
    return write_tet_mesh_TetGen(node_os, ele_os, points, tets, fields) &&
           node_os.flush() && ele_os.flush();
  }
  return false;
}

} // namespace IO
} // namespace CGAL

#endif // CGAL_ISM_RECONSTRUCTION_3_IO_TET_MESH_IO_H
