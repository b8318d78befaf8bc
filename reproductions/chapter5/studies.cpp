// The set's studies as one ensemble (studies.hpp, set.hpp): plan, packings, phase A, phase B,
// measure.
#include "chapter5/studies.hpp"

namespace kolsky::ch5 {

bool run_studies(Study& s, SetEnsemble& e, const std::function<bool(const std::string&)>& wanted) {
  // 1. Plan every study before any run: a missing printed value or threshold fails at once.
  const bool wang = wanted("wang"), huang = wanted("huang"), song = wanted("song");
  const WangPlan wp = wang ? wang_plan(s) : WangPlan{};
  const CaseSpec hp = huang ? huang_plan(s) : CaseSpec{};
  const SongPlan sp = song ? song_plan(s) : SongPlan{};
  // 2. Phase A: the independent cases of every study.
  const CaseRunner r = s.runner();
  WangRuns wr;
  CaseResult huang_case, song_breakage, song_no_breakage;
  if (wang) wang_cases(wp, r, e, wr);
  if (huang) add_case(e, r, hp, &huang_case);
  if (song) add_case(e, r, sp.breakage, &song_breakage), add_case(e, r, sp.no_breakage, &song_no_breakage);
  run_packings(e, r);  // each packing once, before the cases that share it
  run_phase(e, "A");
  // 3. Phase B: the chains on phase A's results (the back-calculations need the reference).
  if (wang) wang_chains(wp, r, e, wr);
  run_phase(e, "B");
  if (ensemble::rank_layout().rank != 0) return false;
  // 4. Measure, in a fixed order: the report does not depend on which member finished first.
  if (wang) wang_measure(s, wp, wr);
  if (huang) huang_measure(s, huang_case);
  if (song) song_measure(s, sp, song_breakage, song_no_breakage);
  return true;
}

}  // namespace kolsky::ch5
