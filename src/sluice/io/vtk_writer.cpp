#include "sluice/io/vtk_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <utility>

#include "sluice/io/atomic_file.hpp"

namespace sluice::io {

namespace {

// The raw appended data is the in-memory representation, declared LittleEndian in the header.
static_assert(std::endian::native == std::endian::little,
              "vtk_writer assumes a little-endian host");

std::string xml_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// One appended block: its UInt64 byte count, then the bytes.
void write_block(AtomicFile& out, const void* data, uint64_t bytes) {
  out.write(&bytes, sizeof bytes);
  out.write(data, bytes);
}

// Block of the Int64 values first, first+step, ..., first+(count-1) step, generated in chunks
// so a large frame needs no second full-size buffer.
void write_iota_block(AtomicFile& out, int64_t first, int64_t count, int64_t step = 1) {
  const uint64_t bytes = static_cast<uint64_t>(count) * sizeof(int64_t);
  out.write(&bytes, sizeof bytes);
  std::array<int64_t, 4096> chunk;
  for (int64_t begin = 0; begin < count; begin += static_cast<int64_t>(chunk.size())) {
    const int64_t size = std::min<int64_t>(static_cast<int64_t>(chunk.size()), count - begin);
    for (int64_t i = 0; i < size; ++i) chunk[i] = first + (begin + i) * step;
    out.write(chunk.data(), static_cast<size_t>(size) * sizeof(int64_t));
  }
}

void check_float_arrays(const std::string& path, const std::vector<PointArrayF32>& arrays,
                        size_t n) {
  for (const PointArrayF32& array : arrays) {
    if (array.components < 1) {
      throw std::invalid_argument(
          fmt::format("'{}': array '{}' has {} components", path, array.name, array.components));
    }
    if (array.values.size() != n * static_cast<size_t>(array.components)) {
      throw std::invalid_argument(
          fmt::format("'{}': array '{}' has {} values, expected {} x {} components", path,
                      array.name, array.values.size(), n, array.components));
    }
  }
}

void check_sizes(const std::string& path, const PolyFrame& frame) {
  auto fail = [&](const std::string& problem) {
    throw std::invalid_argument(fmt::format("write_vtp '{}': {}", path, problem));
  };
  if (frame.points.size() % 3 != 0) {
    fail(fmt::format("points has {} values, not a multiple of 3", frame.points.size()));
  }
  const size_t n = frame.points.size() / 3;
  if (frame.points_per_cell < 1 || frame.points_per_cell > 3 || n % frame.points_per_cell != 0) {
    fail(fmt::format("{} points do not make cells of {}", n, frame.points_per_cell));
  }
  check_float_arrays(path, frame.float_arrays, n);
  for (const PointArrayI32& array : frame.int_arrays) {
    if (array.values.size() != n) {
      fail(
          fmt::format("array '{}' has {} values, expected {}", array.name, array.values.size(), n));
    }
  }
}

}  // namespace

void write_vtp(const std::string& path, const PolyFrame& frame) {
  check_sizes(path, frame);
  const size_t n = frame.points.size() / 3;

  // Offsets count from the byte after the '_' that opens the appended data.
  uint64_t offset = 0;
  auto next_offset = [&offset](uint64_t bytes) {
    const uint64_t at = offset;
    offset += sizeof(uint64_t) + bytes;
    return at;
  };

  std::string xml = fmt::format(
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n"
      "  <PolyData>\n"
      "    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"{}\" NumberOfLines=\"{}\" "
      "NumberOfStrips=\"0\" NumberOfPolys=\"{}\">\n"
      "      <PointData>\n",
      n, frame.points_per_cell == 1 ? n : 0, frame.points_per_cell == 2 ? n / 2 : 0,
      frame.points_per_cell == 3 ? n / 3 : 0);
  for (const PointArrayF32& array : frame.float_arrays) {
    xml += fmt::format(
        "        <DataArray type=\"Float32\" Name=\"{}\" NumberOfComponents=\"{}\" "
        "format=\"appended\" offset=\"{}\"/>\n",
        xml_escape(array.name), array.components, next_offset(array.values.size() * sizeof(float)));
  }
  for (const PointArrayI32& array : frame.int_arrays) {
    xml += fmt::format(
        "        <DataArray type=\"Int32\" Name=\"{}\" format=\"appended\" offset=\"{}\"/>\n",
        xml_escape(array.name), next_offset(array.values.size() * sizeof(int32_t)));
  }
  xml += fmt::format(
      "      </PointData>\n"
      "      <Points>\n"
      "        <DataArray type=\"Float32\" Name=\"Points\" NumberOfComponents=\"3\" "
      "format=\"appended\" offset=\"{}\"/>\n"
      "      </Points>\n",
      next_offset(n * 3 * sizeof(float)));
  // Separate statements: the order in which function arguments are evaluated is unspecified.
  const size_t cell_count = n / static_cast<size_t>(frame.points_per_cell);
  const uint64_t connectivity_offset = next_offset(n * sizeof(int64_t));
  const uint64_t offsets_offset = next_offset(cell_count * sizeof(int64_t));
  const char* section = frame.points_per_cell == 1   ? "Verts"
                        : frame.points_per_cell == 2 ? "Lines"
                                                     : "Polys";
  xml += fmt::format(
      "      <{0}>\n"
      "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"appended\" "
      "offset=\"{1}\"/>\n"
      "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"appended\" offset=\"{2}\"/>\n"
      "      </{0}>\n"
      "    </Piece>\n"
      "  </PolyData>\n"
      "  <AppendedData encoding=\"raw\">\n"
      "   _",
      section, connectivity_offset, offsets_offset);

  AtomicFile out(path);
  out.write(xml);
  for (const PointArrayF32& array : frame.float_arrays) {
    write_block(out, array.values.data(), array.values.size() * sizeof(float));
  }
  for (const PointArrayI32& array : frame.int_arrays) {
    write_block(out, array.values.data(), array.values.size() * sizeof(int32_t));
  }
  write_block(out, frame.points.data(), frame.points.size() * sizeof(float));
  const auto per_cell = static_cast<int64_t>(frame.points_per_cell);
  write_iota_block(out, 0, static_cast<int64_t>(n));  // connectivity: the points in order
  write_iota_block(out, per_cell, static_cast<int64_t>(cell_count), per_cell);  // cells' ends
  out.write("\n  </AppendedData>\n</VTKFile>\n");
  out.commit();
}

void write_pvtp(const std::string& path, const PolyFrame& like,
                const std::vector<std::string>& pieces) {
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"PPolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n"
      "  <PPolyData GhostLevel=\"0\">\n"
      "    <PPointData>\n";
  for (const PointArrayF32& array : like.float_arrays) {
    xml +=
        fmt::format("      <PDataArray type=\"Float32\" Name=\"{}\" NumberOfComponents=\"{}\"/>\n",
                    xml_escape(array.name), array.components);
  }
  for (const PointArrayI32& array : like.int_arrays) {
    xml += fmt::format("      <PDataArray type=\"Int32\" Name=\"{}\"/>\n", xml_escape(array.name));
  }
  xml +=
      "    </PPointData>\n"
      "    <PPoints>\n"
      "      <PDataArray type=\"Float32\" Name=\"Points\" NumberOfComponents=\"3\"/>\n"
      "    </PPoints>\n";
  for (const std::string& piece : pieces)
    xml += fmt::format("    <Piece Source=\"{}\"/>\n", xml_escape(piece));
  xml += "  </PPolyData>\n</VTKFile>\n";
  write_file_atomically(path, xml);
}

void write_vti(const std::string& path, const ImageFrame& frame) {
  size_t n = 1;
  for (const int c : frame.cells) {
    if (c < 1) throw std::invalid_argument(fmt::format("write_vti '{}': {} cells", path, c));
    n *= static_cast<size_t>(c);
  }
  check_float_arrays(path, frame.cell_arrays, n);
  uint64_t offset = 0;
  std::string xml = fmt::format(
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n"
      "  <ImageData WholeExtent=\"0 {0} 0 {1} 0 {2}\" Origin=\"{3:.9g} {4:.9g} {5:.9g}\" "
      "Spacing=\"{6:.9g} {6:.9g} {6:.9g}\">\n"
      "    <Piece Extent=\"0 {0} 0 {1} 0 {2}\">\n"
      "      <CellData>\n",
      frame.cells[0], frame.cells[1] == 1 && frame.cells[2] > 1 ? 0 : frame.cells[1],
      frame.cells[2], frame.origin[0], frame.origin[1], frame.origin[2], frame.spacing);
  for (const PointArrayF32& array : frame.cell_arrays) {
    xml += fmt::format(
        "        <DataArray type=\"Float32\" Name=\"{}\" NumberOfComponents=\"{}\" "
        "format=\"appended\" offset=\"{}\"/>\n",
        xml_escape(array.name), array.components, offset);
    offset += sizeof(uint64_t) + array.values.size() * sizeof(float);
  }
  xml +=
      "      </CellData>\n"
      "    </Piece>\n"
      "  </ImageData>\n"
      "  <AppendedData encoding=\"raw\">\n"
      "   _";
  AtomicFile out(path);
  out.write(xml);
  for (const PointArrayF32& array : frame.cell_arrays) {
    write_block(out, array.values.data(), array.values.size() * sizeof(float));
  }
  out.write("\n  </AppendedData>\n</VTKFile>\n");
  out.commit();
}

PvdSeries::PvdSeries(std::string path) : path_(std::move(path)) {}

void PvdSeries::add(double time, const std::vector<std::string>& files_relative_to_pvd) {
  entries_.emplace_back(time, files_relative_to_pvd);
  write();
}

void PvdSeries::archive_state(StateArchive& a) {
  a(entries_);
  if (a.reading()) write();
}

void PvdSeries::write() const {
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (const auto& [entry_time, files] : entries_) {
    for (size_t part = 0; part < files.size(); ++part) {
      xml += fmt::format("    <DataSet timestep=\"{:.9g}\" group=\"\" part=\"{}\" file=\"{}\"/>\n",
                         entry_time, part, xml_escape(files[part]));
    }
  }
  xml +=
      "  </Collection>\n"
      "</VTKFile>\n";
  write_file_atomically(path_, xml);
}

const std::string& PvdSeries::path() const {
  return path_;
}

void write_file_atomically(const std::string& path, const std::string& text) {
  AtomicFile out(path);
  out.write(text);
  out.commit();
}

}  // namespace sluice::io
