#pragma once
// vmtk / VTK XML PolyData centerlines (.vtp), read without VTK (pugixml + zlib), after the file
// format of VTK's vtkXMLPolyDataWriter (VTK "File Formats" guide, XML section):
// - <Points>: one DataArray of 3 components (Float32 or Float64), physical coordinates (mm, LPS);
// - <Lines>: DataArrays "connectivity" and "offsets" (end offsets); each line cell is one path;
// - <PointData>: the radius, "MaximumInscribedSphereRadius" (vmtk) or else "Radius"; without one
//   the radii are 0 (unknown, with a warning per path);
// - <CellData>: the path names, a String array "CenterlineName" in ascii (as VTK writes strings:
//   each string's bytes as numbers, then a 0; a <DataArray>, or an <Array> as VTK 9 writes string
//   arrays), written by writeCenterlinesVtp; without one, or for
//   an empty name, a path is named by its cell index ("0", "1", ...); one not in ascii (VTK's
//   binary strings) is skipped with a warning;
// - array formats: ascii; binary (base64, a header of UInt32 or UInt64 words, header_type); zlib
//   compression (compressor="vtkZLibDataCompressor": header nblocks, blocksize, lastblocksize,
//   compressed sizes, then the blocks); appended (<AppendedData encoding="raw"|"base64">, offsets on
//   the DataArrays counted from the byte after the leading '_'); either byte order.
// Several <Piece>s are read one after another.
#include <filesystem>
#include <string>

#include "io/centerline_file.h"
#include "vessel/centerline.h"

namespace angio {

// Writes atomically one Piece in ascii (format version 0.1, which every VTK reads; numbers as the
// shortest text that reads back as the same double): Points Float64; Lines Int64 connectivity and
// offsets, one line cell per path with its own points in order (a trunk shared by two paths is
// stored in each, as vmtk does); PointData "MaximumInscribedSphereRadius" Float64; CellData
// "CenterlineName" String. Ascii because VTK reads String arrays in ascii in every version, and
// binary ones not in all. Throws InputError naming the file if it cannot be written;
// `centerlines` must be in the physical frame (std::logic_error otherwise).
void writeCenterlinesVtp(const Centerlines& centerlines, const std::filesystem::path& file);

// Throws InputError naming the file and the problem: bad XML, not PolyData, unsupported
// compressor or data type, arrays of the wrong size, undecodable data, connectivity out of range,
// a name array with a name count other than the cell count, and the model's errors (NaN, negative radius, no paths).
Centerlines readCenterlinesVtp(const std::filesystem::path& file,
                               const CenterlineLoadOptions& options = {});
Centerlines parseCenterlinesVtp(const std::string& bytes, const std::filesystem::path& source,
                                const CenterlineLoadOptions& options = {});

}  // namespace angio
