// Drives the scene-loader fuzz target without libFuzzer: starts from the files given on the command
// line (the shipped scenes), and for a fixed time feeds the target mutants of them made by a seeded
// generator (bytes flipped, inserted, deleted or copied from elsewhere in the file; pieces of two
// files spliced). Deterministic for a seed; exits 0 when every input was handled.
//   scene_fuzz_driver SECONDS SEED FILE...
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size);

namespace
{
    std::string fileText(const char *path)
    {
        std::ifstream in(path, std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        return text.str();
    }

    /** One mutant of corpus[k]: a few random edits, sometimes spliced with another file. */
    std::string mutant(const std::vector<std::string> &corpus, std::mt19937 &rng)
    {
        const auto pick = [&rng](std::size_t n)
        { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
        std::string text = corpus[pick(corpus.size())];
        const std::size_t edits = 1 + pick(4);
        for (std::size_t e = 0; e < edits && !text.empty(); ++e)
        {
            const std::size_t at = pick(text.size());
            switch (pick(5))
            {
                case 0:  // flip a bit
                    text[at] = static_cast<char>(text[at] ^ (1 << pick(8)));
                    break;
                case 1:  // insert a byte that means something in XML or numbers
                    text.insert(at, 1, "<>/=\"'*-.0e9 \n&;#x"[pick(18)]);
                    break;
                case 2:  // delete a run
                    text.erase(at, 1 + pick(16));
                    break;
                case 3:  // copy a run from elsewhere
                {
                    const std::size_t from = pick(text.size());
                    text.insert(at, text.substr(from, 1 + pick(64)));
                    break;
                }
                default:  // splice with another file
                {
                    const std::string &other = corpus[pick(corpus.size())];
                    text = text.substr(0, at) + other.substr(pick(other.size()));
                    break;
                }
            }
        }
        return text;
    }
}  // namespace

int main(int argc, char **argv)
{
    if (argc < 4)
    {
        std::cerr << "usage: scene_fuzz_driver SECONDS SEED FILE...\n";
        return 2;
    }
    const double seconds = std::atof(argv[1]);
    std::mt19937 rng(static_cast<std::mt19937::result_type>(std::strtoul(argv[2], nullptr, 10)));
    std::vector<std::string> corpus;
    for (int i = 3; i < argc; ++i)
    {
        corpus.push_back(fileText(argv[i]));
        if (corpus.back().empty())
        {
            std::cerr << argv[i] << ": empty or unreadable\n";
            return 2;
        }
    }
    const auto start = std::chrono::steady_clock::now();
    std::size_t inputs = 0;
    for (const std::string &text : corpus)  // the files themselves first
        LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t *>(text.data()), text.size()), ++inputs;
    while (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < seconds)
    {
        const std::string text = mutant(corpus, rng);
        LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t *>(text.data()), text.size());
        ++inputs;
    }
    std::cout << "scene_fuzz_driver: " << inputs
              << " inputs, every one loaded or rejected with an InputError\n";
    return 0;
}
