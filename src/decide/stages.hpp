// The stages in one table (doc/architecture.md, "Stages"): for every Stage its name in reports, its
// meaning, and what a contact-only answer reports as "decided by" -- and the classifier's ladder,
// the stages it runs in order as a compile-time list (ladder.hpp unrolls it). A stage is one struct
// with one signature, `static Step run(Climb&)`, defined in its own file (stage_*.hpp, stage_*.cpp).
// A new stage is a Stage enumerator (include/relpos/classify.hpp), a row and a place in the list
// here, and its file.
#pragma once

#include <array>
#include <cstddef>

#include "relpos/classify.hpp"

namespace relpos::detail {

/// What one stage is, wherever it is reported.
struct StageRow {
  Stage stage;
  const char* name;        ///< to_string(Stage): reports, scene counts, Python's STAGE_NAMES
  const char* meaning;     ///< the report's explanation of the stage
  const char* decided_by;  ///< the contact-only answer's "decided_by" (doc/contact.md)
};

inline constexpr StageRow kStageTable[] = {
    {Stage::InsideCertificate, "inside-certificate", "certified inside: P < 0 on the solid ellipsoid (scene early-out)",
     "scene-certificate"},
    {Stage::OutsideCertificate, "outside-certificate",
     "certified outside: P > 0 on the solid ellipsoid (scene early-out)", "scene-certificate"},
    {Stage::DiscriminantFilter, "discriminant-filter",
     "signs of f and Disc(f) certified in double arithmetic, no Sturm-Habicht sequence (contact only)",
     "discriminant-filter"},
    {Stage::StaticDouble, "static-double", "all signs certified in double arithmetic with static error bounds",
     "full-classifier"},
    {Stage::SemiStaticDouble, "semi-static-double",
     "all signs certified in double arithmetic with error bounds from the operands' magnitudes", "full-classifier"},
    {Stage::MultipleRootWitness, "multiple-root-witness",
     "Disc(f) = 0 certified by exact rational multiple roots of f (machine integers)", "full-classifier"},
    {Stage::Interval, "interval", "all signs certified by interval arithmetic", "full-classifier"},
    {Stage::ExactSigns, "exact-signs", "exact integer signs", "full-classifier"},
    {Stage::ExactRoots, "exact-roots", "exact factorisation of f: Disc(f) = 0 or a defective Sturm-Habicht sequence",
     "full-classifier"},
};

/// The row of a stage (the table is in enum order: checked below).
constexpr const StageRow& stage_row(Stage s) { return kStageTable[static_cast<std::size_t>(s)]; }

constexpr bool table_in_enum_order() {
  if (sizeof kStageTable / sizeof kStageTable[0] != kAllStages.size()) return false;
  for (std::size_t i = 0; i < kAllStages.size(); ++i)
    if (kStageTable[i].stage != kAllStages[i] || static_cast<std::size_t>(kAllStages[i]) != i) return false;
  return true;
}
static_assert(table_in_enum_order(), "one row per Stage, in enum order");

/// What a stage did: not applicable to the pair, ran without settling it, or settled it (the
/// climb's verdict is final: decided, or left for the caller's slower path).
enum class Step : unsigned char { Skipped, Open, Done };

struct Climb;  // ladder.hpp

// The classifier's stages. StaticDoubleStage, on every pair's path, is inline (stage_static_double.hpp);
// each other one is defined in its own stage_*.cpp.
struct StaticDoubleStage;
struct SemiStaticDoubleStage {
  static constexpr Stage id = Stage::SemiStaticDouble;
  static Step run(Climb& c);
};
struct MultipleRootWitnessStage {
  static constexpr Stage id = Stage::MultipleRootWitness;
  static Step run(Climb& c);
};
struct IntervalStage {
  static constexpr Stage id = Stage::Interval;
  static Step run(Climb& c);
};
struct ExactSignsStage {
  static constexpr Stage id = Stage::ExactSigns;
  static Step run(Climb& c);
};
struct ExactRootsStage {
  static constexpr Stage id = Stage::ExactRoots;
  static Step run(Climb& c);
};

/// A compile-time list of stages.
template <class... S>
struct StageList {};

/// The classifier's ladder, in the order the stages run (each only while a needed sign is uncertain).
using ClassifierLadder = StageList<StaticDoubleStage, SemiStaticDoubleStage, MultipleRootWitnessStage, IntervalStage,
                                   ExactSignsStage, ExactRootsStage>;

/// The stages of decide_position / classify, in order (a pair classified alone never ends in an early-out).
inline constexpr std::array kClassifierStages{Stage::StaticDouble, Stage::SemiStaticDouble, Stage::MultipleRootWitness,
                                              Stage::Interval,     Stage::ExactSigns,       Stage::ExactRoots};
/// The stages a scene body can end in (scene.hpp), in order: the early-outs, then the classifier's.
inline constexpr std::array kSceneStages{Stage::InsideCertificate, Stage::OutsideCertificate,  Stage::StaticDouble,
                                         Stage::SemiStaticDouble,  Stage::MultipleRootWitness, Stage::Interval,
                                         Stage::ExactSigns,        Stage::ExactRoots};

}  // namespace relpos::detail
