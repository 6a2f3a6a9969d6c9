/* The checks of a COLLADA file that assimp 5.2's reader lacks, made before it reads the file. */
#pragma once

#include <string>

namespace ompl_mm
{
    /** Checks what assimp 5.2's COLLADA reader trusts and misreads: the file is well-formed XML with a
       `<COLLADA>` root; index lists (`<p>`, `<vcount>`, `<v>`, `<h>`) hold only whole numbers (on any other
       character the reader never stops and fills the memory); an array's count (`<float_array>`,
       `<int_array>`,
        `<bool_array>`, `<Name_array>`, `<IDREF_array>`) is given and is the number of values it holds
        (without one, or with 0 and values, it crashes, a smaller one leaves the rest unread); an `<accessor>`
       reads no more than its array holds, count × stride from offset (beyond, it reads past the array's end);
        `<triangles>`, `<lines>` and `<polylist>` of a count above 0 have one `<p>`, and `<polygons>`,
        `<trifans>`, `<tristrips>` and `<linestrips>` as many as their count, each a whole number of
        vertices and at least one primitive's (its assertions abort the process, a short strip
        makes it read past its indices).
        @throws std::runtime_error "line N: ..." at the first element that fails. */
    void checkColladaFile(const std::string &path);
}  // namespace ompl_mm
