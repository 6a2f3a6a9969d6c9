/* A small, stable hash of bytes (FNV-1a, 64 bits): the same on every machine and in every build, for
   seeds derived from names and for telling versions of a file apart. Not for security. */
#pragma once

#include <cstdint>
#include <string_view>

namespace ompl_core
{
    /** FNV-1a's starting value. */
    constexpr std::uint64_t FNV1A_OFFSET = 14695981039346656037ull;

    /** hash continued over bytes (start with FNV1A_OFFSET). */
    constexpr std::uint64_t fnv1a64(std::string_view bytes, std::uint64_t hash = FNV1A_OFFSET)
    {
        for (const char c : bytes)
        {
            hash ^= static_cast<unsigned char>(c);
            hash *= 1099511628211ull;  // FNV's 64-bit prime
        }
        return hash;
    }
}  // namespace ompl_core
