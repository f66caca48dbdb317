// The learner of an experiment file (docs/experiments.md "Learners"): `[learning.learner]` with
// its name and options, or a list of such tables, which makes the learner a grid axis. Read apart
// from the rest of the learning table because a learner's options are its own (checked by
// learning::resolve_learner, not against the run's defaults).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "experiments/document_schema.h"

namespace multicpg::experiments {

// Takes "learner" out of the document's learning table `learning` (when it is a table), so the
// rest is checked against the defaults as before; what it held, if anything.
std::optional<nlohmann::json> take_learner(nlohmann::json& learning);

// Puts the learner `given` (a table, or a list of tables: the grid axis "learning.learner") into
// the resolved learning table `learning`, every learner resolved with its defaults. Throws
// OptionError keyed "learning.learner..." for a learner that is not a table, unknown, has a bad
// option, or appears twice in the list.
void add_learner(const nlohmann::json& given, nlohmann::json& learning,
                 std::vector<GridAxis>& grid);

}  // namespace multicpg::experiments
