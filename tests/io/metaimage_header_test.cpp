// A MetaImage header's fields as MetaIO (ITK's MetaImage reader) reads them: the checks before ITK
// reads a file are only as good as this agreement, so MetaIO itself is the reference here.
#include "io/metaimage_header.h"

#include <gtest/gtest.h>
#include <metaImage.h>

#include <string>

#include "tests/support/file_bytes.h"
#include "tests/support/temp_folder_test.h"

namespace angio {
namespace {

class MetaImageHeaderTest : public test_support::TempFolderTest {
 protected:
  std::filesystem::path write(const std::string& fields) {
    const std::filesystem::path file = dir_ / "h.mhd";
    test_support::overwrite(file, "ObjectType = Image\nNDims = 3\nElementType = MET_SHORT\n" + fields);
    return file;
  }
};

// The whole literal, NULs included.
template <std::size_t size>
std::string withNuls(const char (&text)[size]) {
  return std::string(text, size - 1);
}

// MetaIO's header-only read (no voxels): the data file it names, or "(unread)" if it fails.
std::string metaIoDataFile(const std::filesystem::path& file) {
  MetaImage image;
  if (!image.Read(file.c_str(), false)) return "(unread)";
  return image.ElementDataFileName();
}

TEST_F(MetaImageHeaderTest, FieldNamesWithANulAreComparedAsMetaIoComparesThem) {
  // MetaIO trims the blanks before the separator, then compares the name as a C string: a blank
  // before the NUL stays part of the name, a blank after it does not.
  struct Case {
    std::string fields;
    std::string dataFile;
  };
  const Case cases[] = {
      {withNuls("DimSize = 2 3 2\nElementDataFile \0 = LOCAL\nElementDataFile = x.raw\n"), "x.raw"},
      {withNuls("DimSize = 2 3 2\nElementDataFile\0 = LOCAL\nElementDataFile = x.raw\n"), "LOCAL"},
      {withNuls("DimSize = 2 3 2\nElementDataFile\0junk = a.raw\nElementDataFile = x.raw\n"), "a.raw"},
      {std::string("DimSize = 2 3 2\nElementDataFile  = b.raw\n"), "b.raw"},
  };
  for (const Case& c : cases) {
    const auto file = write(c.fields);
    const MetaImageHeader header = readMetaImageHeader(file);
    EXPECT_EQ(header.field("ElementDataFile"), c.dataFile) << c.fields;
    EXPECT_EQ(metaIoDataFile(file), c.dataFile) << c.fields;
    EXPECT_FALSE(header.unreadableLine) << *header.unreadableLine;
  }
  // A name MetaIO does not know is not DimSize: MetaIO fails for want of one, and so do the checks.
  const auto file = write(withNuls("DimSize\t \0x\t = 2 3 2\nElementDataFile = LOCAL\n"));
  EXPECT_EQ(readMetaImageHeader(file).field("DimSize"), "");
  EXPECT_EQ(metaIoDataFile(file), "(unread)");
}

TEST_F(MetaImageHeaderTest, ControlBytesInAHeaderLineMakeItUnreadable) {
  // MetaIO ends a name at a CR and takes the value after the next '=' (here: DimSize = 2 3 2);
  // it skips a leading vertical tab or form feed. A reader by lines would not see those fields.
  for (const std::string dimSize : {"DimSize\rFoo = 2 3 2", "\v\fDimSize = 2 3 2"}) {
    const auto file = write(dimSize + "\nElementDataFile = x.raw\n");
    ASSERT_EQ(metaIoDataFile(file), "x.raw") << dimSize;
    const MetaImageHeader header = readMetaImageHeader(file);
    ASSERT_TRUE(header.unreadableLine) << dimSize;
    EXPECT_EQ(*header.unreadableLine,
              "header line 4 has the control byte " + std::string(dimSize[0] == '\v' ? "0x0b" : "0x0d"));
  }
  // A CRLF line end and a tab are not control bytes here.
  const auto file = write("DimSize =\t2 3 2\r\nElementDataFile = x.raw\r\n");
  const MetaImageHeader header = readMetaImageHeader(file);
  EXPECT_FALSE(header.unreadableLine) << *header.unreadableLine;
  EXPECT_EQ(header.field("DimSize"), "2 3 2");
  EXPECT_EQ(header.field("ElementDataFile"), "x.raw");
  EXPECT_EQ(metaIoDataFile(file), "x.raw");
}

}  // namespace
}  // namespace angio
