// The choice among a pixel's candidates in the synthesis's correction (synthesis.h): a candidate
// that fits (its exemplar label is the pixel's target label) beats any that does not; among
// candidates of one kind the least cost wins, the earlier on a tie; a NaN cost wins only as the
// first that fits after none did.
//
// Costs are dear (the label mismatch of a neighbourhood, the reuse penalty's window), so each
// candidate offers a floor first, a number its cost is no less than: a candidate that does not
// fit where the winner does is not weighed at all, and one whose floor is not under the least cost
// so far is dismissed unweighed unless it fits where the winner does not (then it wins whatever
// its cost). The winner is the one the whole costs would choose.
#pragma once

#include <cstddef>
#include <limits>

namespace maquette::synthesis {

// Candidates 0 .. n - 1: the winner's index, or -1 when n is 0 or every cost is NaN. fits(i)
// says whether candidate i fits; for each candidate not passed over for not fitting, floor(i) is
// called once, then, unless it dismisses the candidate, cost(i) once. Precondition: cost(i) >=
// floor(i) (a floor of -infinity or NaN bounds any cost).
template <typename Fits, typename Floor, typename Cost>
int least_cost(std::size_t n, Fits&& fits, Floor&& floor, Cost&& cost) {
  int winner = -1;
  bool winner_fits = false;
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    const bool fit = fits(i);
    if (winner_fits && !fit) continue;
    const bool wins_any = fit && !winner_fits;
    const double low = floor(i);
    if (!wins_any && low >= least) continue;
    const double c = cost(i);
    if (c < least || wins_any) least = c, winner = int(i), winner_fits = fit;
  }
  return winner;
}

}  // namespace maquette::synthesis
