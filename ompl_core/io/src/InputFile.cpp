#include "ompl_core/io/InputFile.h"

#include "ompl_core/io/InputError.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace ompl_core
{
    std::string readInputFile(const std::string &path, const std::string &what)
    {
        std::error_code error;
        if (std::filesystem::is_directory(path, error))
            throw InputError(SourceLocation{path, 0}, "is a directory, not a " + what);
        // a device or pipe (/dev/zero) could be read forever; a huge file would exhaust memory
        if (std::filesystem::exists(path, error) && !std::filesystem::is_regular_file(path, error))
            throw InputError(SourceLocation{path, 0}, "is not a regular file, not a " + what);
        const std::uintmax_t size = std::filesystem::file_size(path, error);
        if (!error && size > MAX_INPUT_FILE_BYTES)
            throw InputError(SourceLocation{path, 0}, what + " of " + std::to_string(size) +
                                                          " bytes is larger than the limit of " +
                                                          std::to_string(MAX_INPUT_FILE_BYTES) + " bytes");
        std::ifstream in(path, std::ios::binary);
        if (!in)
            throw InputError(SourceLocation{path, 0}, std::filesystem::exists(path, error)
                                                          ? "cannot read the " + what
                                                          : what + " not found");
        std::ostringstream text;
        text << in.rdbuf();
        return text.str();
    }
}  // namespace ompl_core
