// The seeded driver (fuzz_driver.cpp) runs a libFuzzer target without libFuzzer, on inputs drawn
// deterministically from --seed: what CI runs. A target may define the hooks below; without them the
// driver feeds random byte strings of random length and prints no summary.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace cetview::fuzz {

// Replaces `input` with one input drawn from rng (structure-aware generation, e.g. mutated seeds).
[[gnu::weak]] void generateInput(std::mt19937_64& rng, std::vector<std::uint8_t>& input);

// Prints what the target counted over the run without aborting (quality findings), a few lines.
[[gnu::weak]] void printSummary(std::FILE* out);

}  // namespace cetview::fuzz
