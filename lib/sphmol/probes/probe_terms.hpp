#pragma once
// The terms of one probe's sums at one sample over ranks (probes/probe_observer.hpp,
// at_time_pieces): each rank lists the terms of its own particles with a key that orders them as
// the serial sum adds them, and sends them to rank 0 as bytes (per probe: the count, the keys, the
// values, `stride` per term); rank 0 reads every rank's and adds them in key order, so the sum is
// the serial one to the bit. Keys are unique (a term is one particle's, or one pair's).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <tuple>
#include <vector>

namespace sphmol {

struct ProbeTermKey {
  std::uint64_t a, b, c;  // summed in the order of (a, b, c)
  bool operator<(const ProbeTermKey& o) const { return std::tie(a, b, c) < std::tie(o.a, o.b, o.c); }
};

struct ProbeTerms {
  std::vector<ProbeTermKey> keys;
  std::vector<double> values;
  std::size_t stride = 1;
  void add(const ProbeTermKey& k, std::initializer_list<double> v) {
    keys.push_back(k);
    values.insert(values.end(), v);
  }
  void write(std::vector<std::byte>& out) const {
    const std::uint64_t n = keys.size();
    const auto put = [&](const void* p, std::size_t bytes) {
      const auto* b = static_cast<const std::byte*>(p);
      out.insert(out.end(), b, b + bytes);
    };
    put(&n, sizeof n);
    put(keys.data(), n * sizeof(ProbeTermKey));
    put(values.data(), n * stride * sizeof(double));
  }
  // Appends the terms at `at` in `in`, moving `at` past them.
  void read(const std::vector<std::byte>& in, std::size_t& at) {
    std::uint64_t n = 0;
    std::memcpy(&n, in.data() + at, sizeof n);
    at += sizeof n;
    const std::size_t k0 = keys.size(), v0 = values.size();
    runs.push_back(k0);
    keys.resize(k0 + n);
    values.resize(v0 + n * stride);
    if (n == 0) return;
    std::memcpy(keys.data() + k0, in.data() + at, n * sizeof(ProbeTermKey));
    at += n * sizeof(ProbeTermKey);
    std::memcpy(values.data() + v0, in.data() + at, n * stride * sizeof(double));
    at += n * stride * sizeof(double);
  }
  // The terms' indices in key order. Each rank makes its terms in key order (its own particles in
  // global-id order, visited as the serial sums visit them), so the ranks' runs are merged.
  std::vector<std::size_t> order() const {
    std::vector<std::size_t> o(keys.size());
    for (std::size_t k = 0; k < o.size(); ++k) o[k] = k;
    const auto less = [&](std::size_t x, std::size_t y) { return keys[x] < keys[y]; };
    std::vector<std::size_t> bounds = runs;
    bounds.push_back(o.size());
    bool sorted_runs = true;
    for (std::size_t r = 0; r + 1 < bounds.size() && sorted_runs; ++r)
      sorted_runs = std::is_sorted(keys.begin() + static_cast<long>(bounds[r]), keys.begin() + static_cast<long>(bounds[r + 1]));
    if (!sorted_runs) {
      std::sort(o.begin(), o.end(), less);
      return o;
    }
    for (std::size_t r = 1; r + 1 < bounds.size(); ++r)
      std::inplace_merge(o.begin(), o.begin() + static_cast<long>(bounds[r]), o.begin() + static_cast<long>(bounds[r + 1]), less);
    return o;
  }
  std::vector<std::size_t> runs;  // where each rank's terms start
};


}  // namespace sphmol
