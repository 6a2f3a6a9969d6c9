// What the fuzz targets share: the input as text, scratch files written from it, and the contract
// every reader keeps (any input is read, or rejected with an ompl_core::InputError).
#pragma once

#include "ompl_core/io/InputError.h"

#include <console_bridge/console.h>
#include <ompl/util/Console.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace fuzz
{
    /** OMPL's and urdfdom's log messages silenced before the first input: a fuzzer's inputs are
        rejected by the thousand, and their messages would cost more than reading them. */
    inline const bool loggingSilenced = []
    {
        ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
        console_bridge::setLogLevel(console_bridge::CONSOLE_BRIDGE_LOG_NONE);
        return true;
    }();

    /** The fuzzer's bytes as a string (they may hold zeros and any other byte). */
    inline std::string inputText(const std::uint8_t *data, std::size_t size)
    {
        return std::string(reinterpret_cast<const char *>(data), size);
    }

    /** This process's scratch folder in the system's temporary folder, made on first use and
        removed when the process exits normally. */
    inline const std::filesystem::path &scratchFolder()
    {
        struct Folder
        {
            std::filesystem::path path =
                std::filesystem::temp_directory_path() / ("ompl_mm_fuzz_" + std::to_string(::getpid()));
            Folder() { std::filesystem::create_directories(path); }
            ~Folder()
            {
                std::error_code ignored;
                std::filesystem::remove_all(path, ignored);
            }
        };
        static const Folder folder;
        return folder.path;
    }

    /** Writes text as the scratch file called name; returns its path. */
    inline std::string writeScratchFile(const std::string &name, const std::string &text)
    {
        const std::filesystem::path path = scratchFolder() / name;
        std::ofstream(path, std::ios::binary).write(text.data(), static_cast<std::streamsize>(text.size()));
        return path.string();
    }

    /** Runs read(): an InputError is the reader's rejection and ends the input; any other exception
        escapes, terminates the process and is reported by the fuzzer as a defect. */
    template <typename Read>
    void readOrReject(Read &&read)
    {
        try
        {
            read();
        }
        catch (const ompl_core::InputError &)
        {
        }
    }
}  // namespace fuzz
