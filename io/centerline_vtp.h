#pragma once
// vmtk / VTK XML PolyData centerlines (.vtp), read without VTK (pugixml + zlib), after the file
// format of VTK's vtkXMLPolyDataWriter (VTK "File Formats" guide, XML section):
// - <Points>: one DataArray of 3 components (Float32 or Float64), physical coordinates (mm, LPS);
// - <Lines>: DataArrays "connectivity" and "offsets" (end offsets); each line cell is one path;
// - <PointData>: the radius, "MaximumInscribedSphereRadius" (vmtk) or else "Radius"; without one
//   the radii are 0 (unknown, with a warning per path);
// - array formats: ascii; binary (base64, a header of UInt32 or UInt64 words, header_type); zlib
//   compression (compressor="vtkZLibDataCompressor": header nblocks, blocksize, lastblocksize,
//   compressed sizes, then the blocks); appended (<AppendedData encoding="raw"|"base64">, offsets on
//   the DataArrays counted from the byte after the leading '_'); either byte order.
// Paths are named by their cell index ("0", "1", ...). Several <Piece>s are read one after another.
#include <filesystem>
#include <string>

#include "io/centerline_file.h"
#include "vessel/centerline.h"

namespace angio {

// Throws InputError naming the file and the problem: bad XML, not PolyData, unsupported
// compressor or data type, arrays of the wrong size, undecodable data, connectivity out of range,
// and the model's errors (NaN, negative radius, no paths).
Centerlines readCenterlinesVtp(const std::filesystem::path& file,
                               const CenterlineLoadOptions& options = {});
Centerlines parseCenterlinesVtp(const std::string& bytes, const std::filesystem::path& source,
                                const CenterlineLoadOptions& options = {});

}  // namespace angio
