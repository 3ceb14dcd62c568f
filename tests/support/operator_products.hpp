#pragma once
// Checks a compliance operator's products (normal, tangential, rolling difference) and its self
// terms against the FFT half-space operator on random tractions: the oracle of every dense or
// matrix operator built from the half-space closed forms (annex B.3).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "ferro/contact/mim/influence_operator.hpp"

namespace ferro::test {

inline double max_abs(const contact::mim::Field& f) {
  double m = 0.0;
  for (double v : f) m = std::max(m, std::abs(v));
  return m;
}

/// Products of `op` equal those of `fft` within `product_tolerance` of the largest entry, and its
/// rolling and normal self terms within `self_tolerance` (relative), on tractions drawn from
/// `seed`.
inline void expect_products_equal(contact::mim::ComplianceOperator& fft,
                                  contact::mim::ComplianceOperator& op, unsigned seed,
                                  double product_tolerance, double self_tolerance) {
  using contact::mim::Field;
  const std::size_t n = fft.grid().size();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0e8, 1.0e8);
  Field tx(n), ty(n);
  for (std::size_t i = 0; i < n; ++i) {
    tx[i] = u(rng);
    ty[i] = u(rng);
  }
  Field a(n), b(n), c(n), d(n);
  fft.normal(tx.data(), a.data());
  op.normal(tx.data(), c.data());
  for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(c[i], a[i], product_tolerance * max_abs(a));
  fft.tangential(tx.data(), ty.data(), a.data(), b.data());
  op.tangential(tx.data(), ty.data(), c.data(), d.data());
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_NEAR(c[i], a[i], product_tolerance * max_abs(a));
    EXPECT_NEAR(d[i], b[i], product_tolerance * max_abs(b));
  }
  fft.rolling_difference(tx.data(), ty.data(), a.data(), b.data());
  op.rolling_difference(tx.data(), ty.data(), c.data(), d.data());
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_NEAR(c[i], a[i], product_tolerance * max_abs(a));
    EXPECT_NEAR(d[i], b[i], product_tolerance * max_abs(b));
  }
  EXPECT_NEAR(op.rolling_self(), fft.rolling_self(), self_tolerance * fft.rolling_self());
  EXPECT_NEAR(op.normal_self(), fft.normal_self(), self_tolerance * fft.normal_self());
}

}  // namespace ferro::test
