#pragma once
// The project's own random source. Every random number that can reach an output comes
// from here, so the same seed gives the same bytes with any compiler or standard library
// (std::normal_distribution and std::shuffle differ between libstdc++ and libc++).

#include <cassert>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>
#include <utility>

namespace common {

// xoshiro256** 1.0 (Blackman & Vigna, 2018), seeded through SplitMix64.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) {
    std::uint64_t x = seed;
    for (auto &word : state_) word = splitmix64(x);
  }

  std::uint64_t next_u64() {
    const std::uint64_t result = rotl(state_[1] * 5, 7) * 9;
    const std::uint64_t t = state_[1] << 17;
    state_[2] ^= state_[0];
    state_[3] ^= state_[1];
    state_[1] ^= state_[2];
    state_[0] ^= state_[3];
    state_[2] ^= t;
    state_[3] = rotl(state_[3], 45);
    return result;
  }

  // Rng(seed).normal(), the same value, without seeding the whole state on the ziggurat's
  // fast path (about 98.8 % of seeds): the first draw needs only the second state word.
  // For streams of one variate each (a lidar beam's noise).
  static double first_normal(std::uint64_t seed);

  // Uniform in [0, 1), 53 random bits.
  double uniform01() { return static_cast<double>(next_u64() >> 11) * 0x1.0p-53; }

  // Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform01(); }

  // Uniform integer in [0, bound), bound > 0, without modulo bias (rejection sampling).
  std::uint64_t below(std::uint64_t bound) {
    assert(bound > 0);
    const std::uint64_t threshold = (0 - bound) % bound;  // 2^64 mod bound
    for (;;) {
      const std::uint64_t r = next_u64();
      if (r >= threshold) return r % bound;
    }
  }

  // Standard normal variate: the ziggurat method (Marsaglia & Tsang, 2000) with 128 layers,
  // in Doornik's form (2005): one 64-bit draw gives the uniform and the layer, and about
  // 98.8 % of calls return after one multiply and one compare; the rest test a wedge
  // (two exp) or draw from the tail beyond kZigguratR (two log). Much cheaper than
  // Box–Muller's log, sqrt, sin and cos; exact in distribution.
  double normal();

  double normal(double mean, double stddev) { return mean + stddev * normal(); }

  // Fisher–Yates, the same permutation everywhere for the same seed.
  template <typename T>
  void shuffle(std::span<T> items) {
    for (std::size_t i = items.size(); i > 1; --i) {
      const auto j = static_cast<std::size_t>(below(i));
      std::swap(items[i - 1], items[j]);
    }
  }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  static std::uint64_t splitmix64(std::uint64_t &x) {
    std::uint64_t z = (x += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }

  std::uint64_t state_[4]{};
};

namespace detail {

// The ziggurat's layer edges x[0] > x[1] = R > ... > x[128] = 0 for the standard normal
// density f(x) = exp(-x^2 / 2), each layer (and the base with its tail) of area V.
inline constexpr int kZigguratLayers = 128;
inline constexpr double kZigguratR = 3.442619855899;
inline constexpr double kZigguratV = 9.91256303526217e-3;

struct ZigguratTable {
  double x[kZigguratLayers + 1];
  double ratio[kZigguratLayers];  // x[i + 1] / x[i]: below it, the point is inside layer i

  ZigguratTable() {
    const auto f = [](double v) { return std::exp(-0.5 * v * v); };
    x[0] = kZigguratV / f(kZigguratR);
    x[1] = kZigguratR;
    for (int i = 2; i < kZigguratLayers; ++i) {
      x[i] = std::sqrt(-2.0 * std::log(kZigguratV / x[i - 1] + f(x[i - 1])));
    }
    x[kZigguratLayers] = 0.0;
    for (int i = 0; i < kZigguratLayers; ++i) ratio[i] = x[i + 1] / x[i];
  }
};

inline const ZigguratTable kZiggurat;

}  // namespace detail

inline double Rng::normal() {
  const detail::ZigguratTable &z = detail::kZiggurat;
  for (;;) {
    const std::uint64_t bits = next_u64();
    const auto layer = static_cast<int>(bits & (detail::kZigguratLayers - 1));
    const double u = 2.0 * (static_cast<double>(bits >> 11) * 0x1.0p-53) - 1.0;  // [-1, 1)
    if (std::abs(u) < z.ratio[layer]) return u * z.x[layer];
    if (layer == 0) {
      // The tail beyond R (Marsaglia, 1964).
      double tail = 0.0, y = 0.0;
      do {
        double u1 = uniform01();
        while (u1 <= 0.0) u1 = uniform01();
        double u2 = uniform01();
        while (u2 <= 0.0) u2 = uniform01();
        tail = -std::log(u1) / detail::kZigguratR;
        y = -std::log(u2);
      } while (y + y < tail * tail);
      return u < 0.0 ? -(detail::kZigguratR + tail) : detail::kZigguratR + tail;
    }
    // The wedge between layer's rectangle and the curve.
    const double v = u * z.x[layer];
    const double f0 = std::exp(-0.5 * (z.x[layer] * z.x[layer] - v * v));
    const double f1 = std::exp(-0.5 * (z.x[layer + 1] * z.x[layer + 1] - v * v));
    if (f1 + uniform01() * (f0 - f1) < 1.0) return v;
  }
}

inline double Rng::first_normal(std::uint64_t seed) {
  std::uint64_t x = seed;
  splitmix64(x);  // state_[0]: not read by the first draw
  const std::uint64_t bits = rotl(splitmix64(x) * 5, 7) * 9;  // next_u64()'s first result
  const detail::ZigguratTable &z = detail::kZiggurat;
  const auto layer = static_cast<int>(bits & (detail::kZigguratLayers - 1));
  const double u = 2.0 * (static_cast<double>(bits >> 11) * 0x1.0p-53) - 1.0;
  if (std::abs(u) < z.ratio[layer]) return u * z.x[layer];
  Rng rng(seed);
  return rng.normal();
}

inline constexpr std::uint64_t kDefaultSeed = 42;

}  // namespace common
