#pragma once
// What one step's stages leave for one kind of pair (pipeline/step_pipeline.hpp): the
// body pairs (BodyPair, PairContact) and the body-polygon pairs (StaticPair, StaticContact)
// each fill one PairStage of a StepResult, stage by stage.
#include <ccd/broad_phase/broad_phase.hpp>
#include <ccd/broad_phase/static_index.hpp>
#include <ccd/narrow/contact_result.hpp>

#include <cstdint>
#include <vector>

namespace ccd {

/// A body pair the narrow phase found in contact.
struct PairContact {
  BodyPair pair;
  ContactResult contact;
};

/// A body's contact with a static polygon found by the narrow phase.
struct StaticContact {
  StaticPair pair;
  ContactResult contact;
};

template <class Pair, class Contact>
struct PairStage {
  std::vector<Pair> candidates;     ///< the broad phase's (static index's) pairs
  std::vector<Pair> passed;         ///< of those, pairs the bound's test let through
  std::vector<double> earliest;     ///< per passed pair, the test's earliest possible contact
  std::vector<Contact> contacts;    ///< of those, pairs the narrow phase found in contact
  std::uint64_t tests_saved = 0;    ///< passed pairs the kinematic principle skipped

  /// Empties every stage (the buffers keep their capacity).
  void clear() {
    candidates.clear();
    passed.clear();
    earliest.clear();
    contacts.clear();
    tests_saved = 0;
  }
};

}  // namespace ccd
