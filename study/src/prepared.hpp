// What every row of the study shares: the hinges with their certified outputs, the order errors are
// measured in, the hinges timed, and the wide references error_own is measured against.
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "hinge/oracle/oracle.hpp"
#include "hinge/reference/evaluate.hpp"
#include "hinge/study/study.hpp"

namespace hinge::study::detail {

class Prepared {
 public:
  // Certifies every hinge with the oracle, its fast path switched off (skipping, and counting, those it
  // rejects). Throws
  // hinge::InputError when none is left.
  Prepared(std::vector<StudyHinge> hinges, std::vector<std::array<double, 12>> timing, const ProgressFn& progress);

  std::vector<StudyHinge> hinges;                 // the certified ones
  std::vector<oracle::CertifiedTheta> certified;  // their outputs
  std::vector<std::array<double, 3>> scale;       // per hinge and group: L ||J_f||_F, used where f* == 0
  std::vector<std::size_t> order;  // categories in turn, so that a row cut short by its budget covers them all
  std::vector<std::array<double, 12>> timing;  // the hinges timed
  std::vector<std::string> categories;         // in order of first appearance
  std::size_t skipped = 0;

  // The reference in MPFR at `bits` for hinge i (computed on first use, then kept; absent where the
  // reference cannot evaluate it). Sets MPFR's precision to `bits`.
  const std::optional<reference::ThetaDerivatives<mpfr>>& wide(std::size_t i, unsigned bits) const;

 private:
  mutable std::map<unsigned, std::vector<std::optional<std::optional<reference::ThetaDerivatives<mpfr>>>>> wide_;
};

}  // namespace hinge::study::detail
