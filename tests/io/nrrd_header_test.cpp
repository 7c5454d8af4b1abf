// A NRRD header's lines as teem reads them: its line ends, its kinds of line, where the data start.
#include "io/nrrd_header.h"

#include <gtest/gtest.h>

#include <string>

#include "tests/support/file_bytes.h"
#include "tests/support/temp_folder_test.h"

namespace angio {
namespace {

class NrrdHeaderTest : public test_support::TempFolderTest {};

TEST_F(NrrdHeaderTest, LinesEndAtLfCrOrCrLfAndTheDataStartAfterTheEmptyLine) {
  const std::string lines[] = {"NRRD0004", "type: short", "", "DATA"};
  for (const std::string end : {"\n", "\r", "\r\n"}) {
    const std::string header = lines[0] + end + lines[1] + end + lines[2] + end;
    test_support::overwrite(dir_ / "h.nrrd", header + lines[3]);
    const auto read = readNrrdHeader(dir_ / "h.nrrd");
    ASSERT_TRUE(read) << end.size();
    ASSERT_EQ(read->lines.size(), 1u);
    EXPECT_EQ(read->lines[0].text, "type: short");
    EXPECT_EQ(read->lines[0].number, 2);
    EXPECT_EQ(read->dataStart, header.size());
    EXPECT_EQ(read->crLineEnds, end != "\n");
  }
}

TEST_F(NrrdHeaderTest, CommentsKeyValuePairsAndFieldsAreToldApartAsTeemDoes) {
  const std::string withNul("k:=v\0 with a NUL", 16);
  test_support::overwrite(dir_ / "h.nrrd",
                          "NRRD0005\n"
                          "# sizes: 1 2 3\n"
                          "Segment0_Name:=aorta: true lumen\n"
                          "Space Directions: (1,0,0) (0,1,0) (0,0,1)\n"
                          "data file:  \t volume.raw\n"
                          "odd: a:=b\n" +
                              withNul + "\nno separator\nsizes: 1 2 3\n");
  const auto header = readNrrdHeader(dir_ / "h.nrrd");
  ASSERT_TRUE(header);
  ASSERT_EQ(header->lines.size(), 7u);  // teem stops at the line it cannot read
  EXPECT_EQ(header->lines[0].kind, NrrdLineKind::comment);
  EXPECT_EQ(header->lines[1].kind, NrrdLineKind::keyValue);
  EXPECT_EQ(header->lines[2].kind, NrrdLineKind::field);
  EXPECT_EQ(header->lines[2].name, "spacedirections");  // teem matches names case-insensitively
  EXPECT_EQ(header->field("datafile"), "volume.raw");
  EXPECT_EQ(header->lines[4].kind, NrrdLineKind::field);     // checked, though teem may take a key
  EXPECT_EQ(header->lines[5].kind, NrrdLineKind::keyValue);  // teem reads up to the NUL
  EXPECT_EQ(header->lines[5].text, withNul);
  EXPECT_EQ(header->lines[6].kind, NrrdLineKind::unknown);
  EXPECT_EQ(header->lines[6].number, 8);
  EXPECT_EQ(header->field("sizes"), "");
  EXPECT_FALSE(header->dataStart);  // a detached header may end without an empty line
}

TEST_F(NrrdHeaderTest, LastValueOfAFieldAndCaseOfItsValue) {
  test_support::overwrite(dir_ / "h.nrrd", "NRRD0004\nencoding: RAW\nEncoding: GZip\n\n");
  const auto header = readNrrdHeader(dir_ / "h.nrrd");
  ASSERT_TRUE(header);
  EXPECT_EQ(header->field("encoding"), "GZip");
  EXPECT_EQ(header->field("encoding", true), "gzip");
  EXPECT_EQ(header->field("endian"), "");
}

TEST_F(NrrdHeaderTest, FilesWithoutTheMagicLineHaveNoHeader) {
  test_support::overwrite(dir_ / "h.nrrd", "NRRD\nsizes: 1 2 3\n\n");
  EXPECT_FALSE(readNrrdHeader(dir_ / "h.nrrd"));
  test_support::overwrite(dir_ / "empty.nrrd", "");
  EXPECT_FALSE(readNrrdHeader(dir_ / "empty.nrrd"));
  EXPECT_FALSE(readNrrdHeader(dir_ / "missing.nrrd"));
}

}  // namespace
}  // namespace angio
