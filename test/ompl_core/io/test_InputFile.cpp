// Tests for InputFile: whole files are read; missing files, directories, sockets, devices and files above
// the size limit are InputErrors naming the path.
#include "ompl_core/io/InputFile.h"

#include "common/InputErrors.h"
#include "common/ScratchDirectory.h"

#include <gtest/gtest.h>

#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

using namespace ompl_core;
using ompl_core::test::inputErrorOf;

namespace
{
    /** A fresh, empty scratch directory for this test program. */
    std::filesystem::path scratchDirectory()
    {
        return ompl_core::test::scratchDirectory("ompl_core_test_InputFile_scratch");
    }
}  // namespace

TEST(ReadInputFile, ReadsTheWholeFile)
{
    const std::filesystem::path file = scratchDirectory() / "ok.xml";
    std::ofstream(file, std::ios::binary) << "<r>\r\n</r>\n";
    EXPECT_EQ(readInputFile(file.string(), "scene file"), "<r>\r\n</r>\n");
}

TEST(ReadInputFile, MissingFile)
{
    const std::string path = (scratchDirectory() / "missing.xml").string();
    EXPECT_EQ(inputErrorOf([&] { readInputFile(path, "scene file"); }), path + ": scene file not found");
}

TEST(ReadInputFile, Directory)
{
    const std::string path = scratchDirectory().string();
    EXPECT_EQ(inputErrorOf([&] { readInputFile(path, "scene file"); }),
              path + ": is a directory, not a scene file");
}

TEST(ReadInputFile, UnreadableFile)
{
    // a Unix socket exists and is no directory, but cannot be opened as a file (not even by root)
    const std::filesystem::path file = scratchDirectory() / "socket.xml";
    const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
    ASSERT_GE(fd, 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    ASSERT_LT(file.string().size(), sizeof(address.sun_path));
    std::strcpy(address.sun_path, file.c_str());
    ASSERT_EQ(::bind(fd, reinterpret_cast<const sockaddr *>(&address), sizeof(address)), 0);
    EXPECT_EQ(inputErrorOf([&] { readInputFile(file.string(), "URDF file"); }),
              file.string() + ": is not a regular file, not a URDF file");
    ::close(fd);
}

TEST(ReadInputFile, RejectsDevicesAndHugeFilesBeforeReading)
{
    // /dev/zero would be read forever
    EXPECT_EQ(inputErrorOf([&] { readInputFile("/dev/zero", "scene file"); }),
              "/dev/zero: is not a regular file, not a scene file");
    // a sparse file just over the limit costs no disk; one at the limit is read
    const std::filesystem::path file = scratchDirectory() / "huge.xml";
    {
        std::ofstream(file) << "<r/>";
    }
    std::filesystem::resize_file(file, MAX_INPUT_FILE_BYTES + 1);
    EXPECT_EQ(inputErrorOf([&] { readInputFile(file.string(), "scene file"); }),
              file.string() + ": scene file of 67108865 bytes is larger than the limit of 67108864 bytes");
    std::filesystem::resize_file(file, MAX_INPUT_FILE_BYTES);
    EXPECT_EQ(readInputFile(file.string(), "scene file").size(), MAX_INPUT_FILE_BYTES);
    std::filesystem::remove(file);
}
