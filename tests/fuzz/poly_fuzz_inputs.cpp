// Input generation for poly_fuzz.cpp in the seeded driver (fuzz_driver.cpp): a few valid .poly files
// with random edits (text mode) or random structured inputs, half each.
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "fuzz_driver.h"

namespace {

const char* const kSeeds[] = {
    "4 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n",
    "8 2 1 1\n0 0 0 3 1\n1 10 0 3 1\n2 10 10 3 1\n3 0 10 3 1\n4 3 3 3 2\n5 7 3 3 2\n6 7 7 3 2\n7 3 7 3 2\n"
    "8 1\n0 0 1 1\n1 1 2 1\n2 2 3 1\n3 3 0 1\n4 4 5 2\n5 5 6 2\n6 6 7 2\n7 7 4 2\n1\n0 5 5\n",
    "6 2 0 0\n1 0 0\n2 4 0\n3 4 2\n4 2 2\n5 2 4\n6 0 4\n6 0\n1 1 2\n2 2 3\n3 3 4\n4 4 5\n5 5 6\n6 6 1\n0\n",
    "5 2 0 0 # comment\n1 0 0\n2 1 1\n3 2 2\n4 3 3\n5 1e-300 1e300\n0 0\n0\n",
};

}  // namespace

namespace cetview::fuzz {

void generateInput(std::mt19937_64& rng, std::vector<std::uint8_t>& input) {
  const char alphabet[] = "0123456789 \n.-+e#xnaif";
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
}

}  // namespace cetview::fuzz
