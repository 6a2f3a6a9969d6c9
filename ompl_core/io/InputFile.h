/* Reading a user's input file whole, refusing what cannot be one (devices, directories, huge files). */
#pragma once

#include <cstdint>
#include <string>

namespace ompl_core
{
    /** The largest input file read: 64 MiB, far above any scene or robot description. */
    constexpr std::uintmax_t MAX_INPUT_FILE_BYTES = 64u << 20u;

    /** The whole text of an input file; what names the kind of file in messages ("scene file").
        @throws InputError "path: <what> not found" (or a directory, not a regular file such as
        /dev/zero, larger than MAX_INPUT_FILE_BYTES, or unreadable). */
    std::string readInputFile(const std::string &path, const std::string &what);
}  // namespace ompl_core
