#pragma once
// Reduction factors K_ij applied to Kalker's coefficients, C_ij,r = K_ij C_ij (Toumi eq. 156):
// the one type of K_ij constants (tables of them: kij_table.hpp).
//
// References: Toumi (2016) eq. (156), section 4.2.4, Table 4.1.
// Known deviations: none (data only).

namespace ferro::contact {

/// K_ij [-]; all 1: Kalker's theory unreduced.
struct ReductionFactors {
  double k11 = 1.0;  ///< longitudinal [-]
  double k22 = 1.0;  ///< lateral [-]
  double k23 = 1.0;  ///< lateral/spin coupling [-]
  double k33 = 1.0;  ///< spin [-]
  /// Throws std::invalid_argument naming the field when a factor is not finite or not > 0.
  void validate(const char* where = "reduction") const;
  /// K11 = K22 = K23 = K33 = k.
  [[nodiscard]] static ReductionFactors uniform(double k) { return {k, k, k, k}; }
  /// K11 and K22 given, K23 and K33 following K22 (Toumi (2016) section 4.2.4: the coupling and
  /// spin terms are reduced with the lateral one).
  [[nodiscard]] static ReductionFactors following_k22(double k11, double k22) {
    return {k11, k22, k22, k22};
  }
  friend bool operator==(const ReductionFactors&, const ReductionFactors&) = default;
};

}  // namespace ferro::contact
