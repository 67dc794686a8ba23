#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <vector>

#include "common/random.hpp"

TEST_CASE("Rng: the same seed gives the same sequence, another seed another") {
  common::Rng a(7), b(7), c(8);
  for (int i = 0; i < 100; ++i) {
    const auto va = a.next_u64();
    CHECK(va == b.next_u64());
    CHECK(va != c.next_u64());
  }
}

TEST_CASE("Rng: xoshiro256** seeded by SplitMix64 gives the reference sequence") {
  // Seed 0, computed independently from the published reference algorithms (Python).
  common::Rng rng(0);
  CHECK(rng.next_u64() == 0x99ec5f36cb75f2b4ULL);
  CHECK(rng.next_u64() == 0xbf6e1f784956452aULL);
  CHECK(rng.next_u64() == 0x1a5f849d4933e6e0ULL);
}

TEST_CASE("Rng: uniform01 stays below 1 and below(n) below n") {
  common::Rng rng(1);
  std::array<int, 7> counts{};
  for (int i = 0; i < 70000; ++i) {
    const double u = rng.uniform01();
    REQUIRE(u >= 0.0);
    REQUIRE(u < 1.0);
    const auto k = rng.below(7);
    REQUIRE(k < 7);
    ++counts[k];
  }
  for (const int n : counts) CHECK(std::abs(n - 10000) < 500);
}

TEST_CASE("Rng: normal() has mean 0 and standard deviation 1 over 10^5 samples") {
  common::Rng rng(3);
  const int n = 100000;
  double sum = 0.0, sum_sq = 0.0;
  for (int i = 0; i < n; ++i) {
    const double z = rng.normal();
    sum += z;
    sum_sq += z * z;
  }
  const double mean = sum / n;
  const double sigma = std::sqrt(sum_sq / n - mean * mean);
  CHECK(std::abs(mean) < 0.02);
  CHECK(std::abs(sigma - 1.0) < 0.03);
}

TEST_CASE("Rng: shuffle is a permutation and depends only on the seed") {
  std::vector<int> a(50), b(50);
  std::iota(a.begin(), a.end(), 0);
  std::iota(b.begin(), b.end(), 0);
  common::Rng ra(11), rb(11);
  ra.shuffle(std::span<int>(a));
  rb.shuffle(std::span<int>(b));
  CHECK(a == b);
  std::vector<int> sorted = a;
  std::sort(sorted.begin(), sorted.end());
  std::vector<int> expected(50);
  std::iota(expected.begin(), expected.end(), 0);
  CHECK(sorted == expected);
  CHECK(a != expected);
}

TEST_CASE("Rng: normal() follows the standard normal distribution in the body and the tails") {
  // 10^6 samples against Phi: every bin's count within 5 standard errors of its expectation,
  // including the ziggurat's tail beyond R = 3.4426 and its wedge layers.
  common::Rng rng(12);
  const int n = 1000000;
  const double edges[] = {-4.0, -3.4426, -3.0, -2.0, -1.0, -0.5, 0.0, 0.5, 1.0, 2.0, 3.0, 3.4426, 4.0};
  const auto phi = [](double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); };
  std::vector<int> counts(std::size(edges) + 1, 0);
  for (int i = 0; i < n; ++i) {
    const double z = rng.normal();
    REQUIRE(std::isfinite(z));
    std::size_t bin = 0;
    while (bin < std::size(edges) && z >= edges[bin]) ++bin;
    ++counts[bin];
  }
  for (std::size_t bin = 0; bin < counts.size(); ++bin) {
    const double lo = bin == 0 ? 0.0 : phi(edges[bin - 1]);
    const double hi = bin == std::size(edges) ? 1.0 : phi(edges[bin]);
    const double expected = n * (hi - lo);
    CAPTURE(bin);
    CAPTURE(counts[bin]);
    CAPTURE(expected);
    CHECK(std::abs(counts[bin] - expected) < 5.0 * std::sqrt(expected) + 1.0);
  }
}

TEST_CASE("Rng: first_normal(seed) is Rng(seed).normal(), on the fast path and off it") {
  int slow_path = 0;
  for (std::uint64_t seed = 0; seed < 20000; ++seed) {
    const std::uint64_t s = seed * 0x9e3779b97f4a7c15ULL;
    common::Rng rng(s);
    const double expected = rng.normal();
    CHECK(common::Rng::first_normal(s) == expected);
    common::Rng again(s);
    const std::uint64_t bits = again.next_u64();
    const double u = 2.0 * (static_cast<double>(bits >> 11) * 0x1.0p-53) - 1.0;
    if (std::abs(u) >= common::detail::kZiggurat.ratio[bits & 127]) ++slow_path;
  }
  CHECK(slow_path > 100);  // the fallback was exercised (about 1.2 % of seeds)
}
