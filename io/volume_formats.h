#pragma once
// The volume file formats of io/ (MetaImage, NRRD, NIfTI), chosen by extension, and small ITK
// helpers shared by the volume reader and writer. ITK's ImageIO objects are created explicitly
// rather than through its factory registry, so nothing depends on factory registration.
#include <filesystem>
#include <optional>
#include <string>

#include <itkImageIOBase.h>

namespace angio {

enum class VolumeFormat { metaImage, nrrd, nifti };

// By case-insensitive extension: .mha .mhd | .nrrd .nhdr | .nii .nii.gz. Empty if none of these.
std::optional<VolumeFormat> volumeFormatOf(const std::filesystem::path& path);
const char* formatName(VolumeFormat format);
itk::ImageIOBase::Pointer makeImageIO(VolumeFormat format);

// "int16", "float32", ... as users know them.
std::string componentTypeName(itk::IOComponentEnum type);

// ITK's exception description squeezed onto one line (it may span several and name source files).
std::string oneLine(const itk::ExceptionObject& error);

// A library's message about voxel data it could not read, in our words where we know what it
// means (MetaIO's for data as text), else unchanged.
std::string readProblemInOurWords(const std::string& text);

}  // namespace angio
