/* An output file of the apps (JSON, SVG, path), written so that a failed write is never silent and
   never leaves a half-written file behind. */
#pragma once

#include "ompl_core/io/InputError.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace apps
{
    /** Writing an output file failed after planning (a full disk, say): exit status 1. */
    struct OutputError : std::runtime_error
    {
        using std::runtime_error::runtime_error;
    };

    /** An output file, created when constructed so that a bad path fails before planning. A regular
        file is written under a temporary name beside it and renamed over it by commit(), so a failed
        write leaves the old file (or none) in place; a device or pipe (/dev/stdout) and a symbolic
        link are written directly. An empty path is no file: isOpen() is false. */
    class OutputFile
    {
    public:
        /** @throws ompl_core::InputError when the file cannot be created. */
        explicit OutputFile(std::string path) : path_(std::move(path))
        {
            if (path_.empty())
                return;
            // a device, a pipe or a symbolic link is written in place: a rename would replace it
            std::error_code error;
            const bool inPlace =
                std::filesystem::is_symlink(std::filesystem::symlink_status(path_, error)) ||
                (std::filesystem::exists(path_, error) && !std::filesystem::is_regular_file(path_, error));
            writing_ = inPlace ? path_ : path_ + ".tmp" + std::to_string(::getpid());
            out_.open(writing_);
            if (!out_)
                throw ompl_core::InputError(path_ + ": cannot write file");
        }

        OutputFile(const OutputFile &) = delete;
        OutputFile &operator=(const OutputFile &) = delete;

        /** Removes the temporary file of an output never committed. */
        ~OutputFile()
        {
            out_.close();
            if (!committed_ && !writing_.empty() && writing_ != path_)
                std::remove(writing_.c_str());
        }

        bool isOpen() const { return out_.is_open(); }

        std::ostream &stream() { return out_; }

        /** Closes the file and puts it in place. @throws OutputError naming the path when any write,
            the close or the rename failed. */
        void commit()
        {
            out_.close();
            if (out_.fail())
                throw OutputError(path_ + ": writing the file failed");
            if (writing_ != path_ && std::rename(writing_.c_str(), path_.c_str()) != 0)
                throw OutputError(path_ + ": cannot put the written file in place");
            committed_ = true;
        }

    private:
        std::string path_;
        std::string writing_;  ///< the temporary file, or path_ itself for a device
        std::ofstream out_;
        bool committed_{false};
    };
}  // namespace apps
