// A scratch folder per test program, for tests that write files.
#pragma once

#include <filesystem>
#include <string>

namespace ompl_core::test
{
    /** A fresh, empty folder named name in the system's temporary folder. */
    inline std::filesystem::path scratchDirectory(const std::string &name)
    {
        const std::filesystem::path dir = std::filesystem::temp_directory_path() / name;
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir);
        return dir;
    }
}  // namespace ompl_core::test
