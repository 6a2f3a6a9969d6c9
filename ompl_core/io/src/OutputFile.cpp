#include "ompl_core/io/OutputFile.h"

#include "ompl_core/io/InputError.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <utility>

namespace ompl_core
{
    OutputFile::OutputFile(std::string path) : path_(std::move(path))
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
            throw InputError(path_ + ": cannot write file");
    }

    OutputFile::~OutputFile()
    {
        out_.close();
        if (!committed_ && !writing_.empty() && writing_ != path_)
            std::remove(writing_.c_str());
    }

    void OutputFile::commit()
    {
        out_.close();
        if (out_.fail())
            throw OutputError(path_ + ": writing the file failed");
        if (writing_ != path_ && std::rename(writing_.c_str(), path_.c_str()) != 0)
            throw OutputError(path_ + ": cannot put the written file in place");
        committed_ = true;
    }
}  // namespace ompl_core
