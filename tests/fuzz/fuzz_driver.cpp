// Seeded driver for any libFuzzer target in this folder (linked with one target's source): replays the
// files and directories named on the command line, then feeds --iterations (default 2000, or none
// when files are given) or --seconds of inputs,
// input i drawn from its own generator seeded by (--seed, i) so one input replays alone with
// --first i --iterations 1. Inputs come from the target's generateInput hook, else random bytes.
// On an abort or crash it names the input and writes it to ./crash-<seed>-<i> (libFuzzer and this
// driver both replay such a file).
//
//   DRIVER [--seed S] [--iterations N | --seconds T] [--first I] [--max-len L] [--verbose] [--save DIR]
//          [FILE|DIR]...
// (--verbose prints each input's time; --save writes each generated input to DIR/<seed>-<i>.)
#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include "fuzz_driver.h"

namespace {

// What the crash handler reports: set before each input, read only by the handler.
char gCrashNote[512];
char gCrashFile[128];
const std::uint8_t* gInput = nullptr;
std::size_t gInputSize = 0;

void onCrash(int sig) {
  // Async-signal-safe calls only.
  ssize_t ignored = ::write(STDERR_FILENO, gCrashNote, std::strlen(gCrashNote));
  if (gCrashFile[0] != '\0') {
    const int fd = ::open(gCrashFile, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      ignored = ::write(fd, gInput, gInputSize);
      ::close(fd);
    }
  }
  (void)ignored;
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

// Under AddressSanitizer its own handler reports memory faults (with a stack); only aborts are ours.
#if defined(__SANITIZE_ADDRESS__)
#define CETVIEW_FUZZ_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CETVIEW_FUZZ_ASAN 1
#endif
#endif

void installCrashHandler() {
  ::signal(SIGABRT, onCrash);
#ifndef CETVIEW_FUZZ_ASAN
  ::signal(SIGSEGV, onCrash);
  ::signal(SIGBUS, onCrash);
  ::signal(SIGFPE, onCrash);
#endif
}

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

std::vector<std::string> listInputs(const std::vector<std::string>& paths) {
  namespace fs = std::filesystem;
  std::vector<std::string> files;
  for (const std::string& p : paths) {
    std::error_code ec;
    if (fs::is_directory(p, ec)) {
      std::vector<std::string> inDir;
      for (const auto& entry : fs::directory_iterator(p, ec))
        if (entry.is_regular_file()) inDir.push_back(entry.path().string());
      std::sort(inDir.begin(), inDir.end());
      files.insert(files.end(), inDir.begin(), inDir.end());
    } else {
      files.push_back(p);
    }
  }
  return files;
}

}  // namespace

int main(int argc, char** argv) {
  std::string name = argv[0];
  name = name.substr(name.find_last_of('/') + 1);
  std::uint64_t seed = 1;
  long iterations = -1, first = 0;  // default: 2000, or none when files are replayed
  double seconds = 0;
  std::size_t maxLen = 512;
  bool verbose = false;
  std::string saveDir;
  std::vector<std::string> paths;
  for (int i = 1; i < argc; ++i) {
    const bool hasValue = i + 1 < argc;
    if (!std::strcmp(argv[i], "--seed") && hasValue) {
      seed = std::strtoull(argv[++i], nullptr, 10);
    } else if (!std::strcmp(argv[i], "--iterations") && hasValue) {
      iterations = std::atol(argv[++i]);
    } else if (!std::strcmp(argv[i], "--seconds") && hasValue) {
      seconds = std::atof(argv[++i]);
    } else if (!std::strcmp(argv[i], "--first") && hasValue) {
      first = std::atol(argv[++i]);
    } else if (!std::strcmp(argv[i], "--max-len") && hasValue) {
      maxLen = std::max<std::size_t>(1, std::strtoull(argv[++i], nullptr, 10));
    } else if (!std::strcmp(argv[i], "--save") && hasValue) {
      saveDir = argv[++i];
    } else if (!std::strcmp(argv[i], "--verbose")) {
      verbose = true;
    } else if (argv[i][0] == '-') {
      std::fprintf(stderr, "%s: unknown option %s\n", name.c_str(), argv[i]);
      return 2;
    } else {
      paths.push_back(argv[i]);
    }
  }
  if (iterations < 0) iterations = paths.empty() || seconds > 0 ? 2000 : 0;
  installCrashHandler();

  const auto start = std::chrono::steady_clock::now();
  double slowest = 0;
  std::string slowestLabel = "none";
  long done = 0;
  auto runOne = [&](const std::vector<std::uint8_t>& input, const std::string& label, const std::string& replay) {
    std::snprintf(gCrashNote, sizeof gCrashNote, "%s: crashed on %s; replay: %s\n", name.c_str(), label.c_str(),
                  replay.c_str());
    gInput = input.data();
    gInputSize = input.size();
    const auto t0 = std::chrono::steady_clock::now();
    LLVMFuzzerTestOneInput(input.data(), input.size());
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (verbose) std::printf("%s: %s, %zu bytes, %.3f s\n", name.c_str(), label.c_str(), input.size(), s), std::fflush(stdout);
    if (s > slowest) slowest = s, slowestLabel = label + " (" + std::to_string(input.size()) + " bytes)";
    ++done;
  };

  const std::vector<std::string> files = listInputs(paths);
  for (const std::string& f : files) {
    std::ifstream in(f, std::ios::binary);
    if (!in) {
      std::fprintf(stderr, "%s: cannot read %s\n", name.c_str(), f.c_str());
      return 2;
    }
    const std::vector<std::uint8_t> input((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    runOne(input, f, std::string(argv[0]) + " " + f);
  }

  std::vector<std::uint8_t> input;
  long generated = 0;
  for (long i = first;; ++i, ++generated) {
    if (seconds > 0) {
      if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > seconds) break;
    } else if (generated >= iterations) {
      break;
    }
    std::mt19937_64 rng(splitmix64(seed ^ splitmix64(static_cast<std::uint64_t>(i))));
    input.clear();
    if (cetview::fuzz::generateInput) {
      cetview::fuzz::generateInput(rng, input);
    } else {
      const std::size_t cap = std::min<std::size_t>(maxLen, std::size_t{8} << (rng() % 7));
      input.resize(1 + rng() % cap);
      for (std::uint8_t& b : input) b = static_cast<std::uint8_t>(rng());
    }
    std::snprintf(gCrashFile, sizeof gCrashFile, "crash-%llu-%ld", static_cast<unsigned long long>(seed), i);
    if (!saveDir.empty()) {
      std::ofstream(saveDir + "/" + std::to_string(seed) + "-" + std::to_string(i), std::ios::binary)
          .write(reinterpret_cast<const char*>(input.data()), static_cast<std::streamsize>(input.size()));
    }
    const std::string label = "input #" + std::to_string(i);
    runOne(input, label,
           std::string(argv[0]) + " --seed " + std::to_string(seed) + " --first " + std::to_string(i) +
               " --iterations 1 (written to ./" + gCrashFile + ")");
  }
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%s: %ld inputs (%zu files, %ld generated, seed %llu) in %.1f s, slowest %.3f s: %s\n", name.c_str(),
              done, files.size(), generated, static_cast<unsigned long long>(seed), total, slowest,
              slowestLabel.c_str());
  if (cetview::fuzz::printSummary) cetview::fuzz::printSummary(stdout);
  std::printf("%s: no finding\n", name.c_str());
  return 0;
}
