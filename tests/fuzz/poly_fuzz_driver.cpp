// Seeded driver for poly_fuzz.cpp when libFuzzer is not used: mutates a few valid .poly files and
// random structured inputs, deterministically from --seed, for --iterations rounds or --seconds.
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

const char* const kSeeds[] = {
    "4 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n",
    "8 2 1 1\n0 0 0 3 1\n1 10 0 3 1\n2 10 10 3 1\n3 0 10 3 1\n4 3 3 3 2\n5 7 3 3 2\n6 7 7 3 2\n7 3 7 3 2\n"
    "8 1\n0 0 1 1\n1 1 2 1\n2 2 3 1\n3 3 0 1\n4 4 5 2\n5 5 6 2\n6 6 7 2\n7 7 4 2\n1\n0 5 5\n",
    "6 2 0 0\n1 0 0\n2 4 0\n3 4 2\n4 2 2\n5 2 4\n6 0 4\n6 0\n1 1 2\n2 2 3\n3 3 4\n4 4 5\n5 5 6\n6 6 1\n0\n",
    "5 2 0 0 # comment\n1 0 0\n2 1 1\n3 2 2\n4 3 3\n5 1e-300 1e300\n0 0\n0\n",
};

}  // namespace

int main(int argc, char** argv) {
  std::uint64_t seed = 1;
  long iterations = 2000;
  double seconds = 0;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--seed")) seed = std::strtoull(argv[i + 1], nullptr, 10);
    if (!std::strcmp(argv[i], "--iterations")) iterations = std::atol(argv[i + 1]);
    if (!std::strcmp(argv[i], "--seconds")) seconds = std::atof(argv[i + 1]);
  }
  std::mt19937_64 rng(seed);
  const auto start = std::chrono::steady_clock::now();
  long done = 0;
  const char alphabet[] = "0123456789 \n.-+e#xnaif";
  for (;; ++done) {
    if (seconds > 0) {
      if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > seconds) break;
    } else if (done >= iterations) {
      break;
    }
    std::vector<std::uint8_t> input;
    if (rng() % 2 == 0) {
      input.push_back(0);  // text mode
      const std::string base = kSeeds[rng() % (sizeof kSeeds / sizeof kSeeds[0])];
      input.insert(input.end(), base.begin(), base.end());
      const int edits = 1 + static_cast<int>(rng() % 6);
      for (int e = 0; e < edits && input.size() > 1; ++e) {
        const std::size_t at = 1 + rng() % (input.size() - 1);
        switch (rng() % 4) {
          case 0: input[at] = static_cast<std::uint8_t>(alphabet[rng() % (sizeof alphabet - 1)]); break;
          case 1: input.erase(input.begin() + static_cast<long>(at)); break;
          case 2: input.insert(input.begin() + static_cast<long>(at), static_cast<std::uint8_t>(alphabet[rng() % (sizeof alphabet - 1)])); break;
          default: input.resize(at); break;  // truncation
        }
      }
    } else {
      input.push_back(1);  // structured mode
      const std::size_t size = 4 + rng() % 200;
      for (std::size_t k = 0; k < size; ++k) input.push_back(static_cast<std::uint8_t>(rng()));
    }
    LLVMFuzzerTestOneInput(input.data(), input.size());
  }
  std::printf("poly_fuzz_driver: %ld inputs, seed %llu, no finding\n", done, static_cast<unsigned long long>(seed));
  return 0;
}
