// Replays every saved fuzz input -- the regressions (fuzz/regressions/<harness>/, inputs that once
// crashed, hung or broke an invariant) and the seed corpus (fuzz/corpus/<harness>/) -- through the
// same checks the libFuzzer harnesses run (fuzz/harnesses.hpp), in the ordinary g++ build. A check
// returns, or throws relpos_fuzz::Defect naming the broken invariant (doc/testing.md).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "../fuzz/harnesses.hpp"
#include "io/batch.hpp"

namespace {

namespace fs = std::filesystem;

/// The files of a directory in name order (README.md and other notes excluded).
std::vector<fs::path> inputs(const fs::path& dir) {
  std::vector<fs::path> out;
  if (!fs::is_directory(dir)) return out;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().extension() != ".md") out.push_back(entry.path());
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::uint8_t> read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

template <class Check>
int replay(const std::string& harness, Check check) {
  int n = 0;
  for (const char* kind : {"regressions", "corpus"}) {
    for (const auto& p : inputs(fs::path(RELPOS_SOURCE_DIR) / "fuzz" / kind / harness)) {
      const std::vector<std::uint8_t> bytes = read_bytes(p);
      INFO(p.string());
      try {
        check(bytes.data(), bytes.size());
      } catch (const relpos_fuzz::Defect& d) {
        FAIL("defect: " << d.what());
      } catch (const std::exception& e) {
        FAIL("unexpected exception: " << e.what());
      }
      ++n;
    }
  }
  return n;
}

}  // namespace

TEST_CASE("fuzz inputs: numbers", "[fuzz][numbers]") { CHECK(replay("numbers", relpos_fuzz::check_numbers) > 10); }

TEST_CASE("fuzz inputs: batch lines", "[fuzz][batch]") {
  CHECK(replay("batch_line", relpos_fuzz::check_batch_line) > 10);
}

TEST_CASE("fuzz inputs: classifier", "[fuzz][classify]") {
  CHECK(replay("classify", relpos_fuzz::check_classify) > 10);
}

TEST_CASE("regression: pairs beyond the size limit are refused quickly, with the limit named", "[fuzz][batch]") {
  // 10^4-digit entries used to keep CGAL's modular gcd looping ("primes in the array exhausted") or
  // to grow past 10 GB of memory (fuzz/regressions/batch_line/README.md).
  for (const char* name : {"cgal-gcd-primes-exhausted", "huge-sphere-memory"}) {
    const auto bytes = read_bytes(fs::path(RELPOS_SOURCE_DIR) / "fuzz/regressions/batch_line" / name);
    std::string line(bytes.begin(), bytes.end());
    while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
    const auto answer =
        nlohmann::json::parse(relpos::detail::io::answer_batch_line(line, 1, relpos::detail::io::BatchOptions{}));
    REQUIRE(answer.contains("error"));
    CHECK_THAT(answer["error"].get<std::string>(), Catch::Matchers::Contains("numbers too large"));
  }
}
