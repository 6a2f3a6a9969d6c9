// Drives a fuzz target without libFuzzer (the gcc builds): feeds it the files given on the command
// line (a folder gives every file in it, in name order: a corpus, the regression inputs), then for a
// fixed time mutants of them made by a seeded generator (bytes flipped, inserted, deleted or copied
// from elsewhere in the file; pieces of two files spliced). Deterministic for a seed; exits 0 when
// every input was handled. On a crash (a signal: a fault, an abort, a sanitizer's report) the input
// that caused it is written to fuzz_driver-crash in the working folder, to replay or keep.
//   fuzz_driver SECONDS SEED FILE_OR_FOLDER...
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size);

namespace
{
    /** The input being read, for the crash handler. */
    const std::string *currentInput = nullptr;

    /** Writes the current input to fuzz_driver-crash (with calls safe in a signal handler), then
        lets the signal take its default course. */
    void keepCrashingInput(int signal)
    {
        if (currentInput != nullptr)
        {
            const int file = ::open("fuzz_driver-crash", O_WRONLY | O_CREAT | O_TRUNC, 0644);
            if (file >= 0)
            {
                [[maybe_unused]] const ssize_t written =
                    ::write(file, currentInput->data(), currentInput->size());
                ::close(file);
            }
        }
        std::signal(signal, SIG_DFL);
        std::raise(signal);
    }

    void read(const std::string &text)
    {
        currentInput = &text;
        LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t *>(text.data()), text.size());
        currentInput = nullptr;
    }

    std::string fileText(const std::filesystem::path &path)
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
                case 1:  // insert a byte that means something in XML, cfg files or numbers
                    text.insert(at, 1, "<>/=\"'*-.0e9 \n&;#x[]"[pick(20)]);
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

    /** The files of path: itself, or a folder's regular files in name order. */
    std::vector<std::filesystem::path> inputFiles(const std::filesystem::path &path)
    {
        if (!std::filesystem::is_directory(path))
            return {path};
        std::vector<std::filesystem::path> files;
        for (const auto &entry : std::filesystem::directory_iterator(path))
            if (entry.is_regular_file())
                files.push_back(entry.path());
        std::sort(files.begin(), files.end());
        return files;
    }
}  // namespace

int main(int argc, char **argv)
{
    if (argc < 4)
    {
        std::cerr << "usage: fuzz_driver SECONDS SEED FILE_OR_FOLDER...\n";
        return 2;
    }
    const double seconds = std::atof(argv[1]);
    std::mt19937 rng(static_cast<std::mt19937::result_type>(std::strtoul(argv[2], nullptr, 10)));
    std::vector<std::string> corpus;
    for (int i = 3; i < argc; ++i)
        for (const std::filesystem::path &file : inputFiles(argv[i]))
        {
            corpus.push_back(fileText(file));
            if (corpus.back().empty())
            {
                std::cerr << file.string() << ": empty or unreadable\n";
                return 2;
            }
        }
    if (corpus.empty())
    {
        std::cerr << "fuzz_driver: no input file\n";
        return 2;
    }
    for (const int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT})
        std::signal(signal, keepCrashingInput);
    const auto start = std::chrono::steady_clock::now();
    std::size_t inputs = 0;
    for (const std::string &text : corpus)  // the files themselves first
        read(text), ++inputs;
    while (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < seconds)
    {
        const std::string text = mutant(corpus, rng);
        read(text);
        ++inputs;
    }
    std::cout << "fuzz_driver: " << inputs << " inputs, every one read or rejected with an InputError\n";
    return 0;
}
