/* An output file (JSON, SVG, path, benchmark log), written so that a failed write is never silent
   and never leaves a half-written file behind. */
#pragma once

#include <fstream>
#include <stdexcept>
#include <string>

namespace ompl_core
{
    /** Writing an output file failed after planning (a full disk, say). The apps exit with status 1. */
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
        /** @throws InputError when the file cannot be created. */
        explicit OutputFile(std::string path);

        OutputFile(const OutputFile &) = delete;
        OutputFile &operator=(const OutputFile &) = delete;

        /** Removes the temporary file of an output never committed. */
        ~OutputFile();

        /** Whether there is a file (its path was not empty). */
        bool isOpen() const { return out_.is_open(); }

        /** Where the file's text goes before commit(). */
        std::ostream &stream() { return out_; }

        /** Closes the file and puts it in place. @throws OutputError naming the path when any write,
            the close or the rename failed. */
        void commit();

    private:
        std::string path_;
        std::string writing_;  ///< the temporary file, or path_ itself for a device
        std::ofstream out_;
        bool committed_{false};
    };
}  // namespace ompl_core
