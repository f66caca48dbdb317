// The landscape figure of a landscape run: report/figures.h's plot_landscape fed from
// experiments/landscape.h.
#pragma once

#include <filesystem>
#include <vector>

#include "experiments/landscape.h"
#include "report/figures.h"

namespace multicpg::report {

// Draws <out_dir>/landscape.{png,svg,csv}; `learned` are every-leg combinations of the
// landscape (experiments::parse_learned), each marked where it falls.
FigureFiles draw_landscape(const experiments::Landscape& landscape,
                           const std::vector<learning::Periods>& learned,
                           const std::filesystem::path& out_dir);

}  // namespace multicpg::report
