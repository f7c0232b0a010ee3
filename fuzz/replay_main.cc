// main() of a fuzz target built without libFuzzer: runs the target's entry
// point once on every file named on the command line, or in a directory
// named there (a corpus), so that ctest checks that every input of the
// corpus stays accepted or cleanly refused. A finding aborts, as in the
// fuzzer.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size);
// Optional in a target, as in libFuzzer.
extern "C" int
LLVMFuzzerInitialize(int *argc, char ***argv) __attribute__((weak));

namespace
{
  void
  replay(const std::filesystem::path &file)
  {
    std::ifstream in(file, std::ios::binary);
    if (!in)
      throw std::runtime_error("cannot open " + file.string());
    const std::vector<std::uint8_t> bytes(std::istreambuf_iterator<char>(in),
                                          {});
    // Names the input that a finding's abort leaves as the last line.
    std::cout << file.string() << std::endl;
    LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
  }
} // namespace

int
main(int argc, char **argv)
{
  if (LLVMFuzzerInitialize != nullptr)
    LLVMFuzzerInitialize(&argc, &argv);
  std::vector<std::filesystem::path> files;
  for (int i = 1; i < argc; ++i)
    if (std::filesystem::is_directory(argv[i]))
      for (const auto &entry : std::filesystem::directory_iterator(argv[i]))
        files.push_back(entry.path());
    else
      files.emplace_back(argv[i]);
  std::sort(files.begin(), files.end());
  if (files.empty())
    {
      std::cerr << "usage: " << argv[0] << " FILE|CORPUS_DIRECTORY...\n"
                << "(no input files found)\n";
      return 1;
    }
  for (const auto &file : files)
    replay(file);
  std::cout << files.size() << " inputs replayed, no finding\n";
  return 0;
}
