/* ----------------------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the water settings of fix cell/fluid (cell_water_settings.h)

     Pi value | Lp value | cell M Pi value Lp value | cells file
     | solute yes/no | exchange yes/no | external psi value
     | external flux value | exposed outside D | exposed unglued | medium air
     | share particle/volume
------------------------------------------------------------------------- */

#include "cell_water_settings.h"

#include "cell_checks.h"
#include "error.h"
#include "force.h"
#include "lammps.h"
#include "utils.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>

using namespace LAMMPS_NS;

namespace {
// default of exposed outside, in Angstrom (10 um): wider than the voids at the rounded edges and
// corners of a cellgen.py tissue (8 um would do at rest, unglued), so that a cell with no free face
// has no exposed wall (docs/fix_cell_fluid.rst, *The outside*)
constexpr double EXPOSE_DEPTH_ANGSTROM = 1.0e5;

// utils::numeric's own error would not say which keyword, file or line the text came from
void require_number(LAMMPS *lmp, const char *text, const std::string &name)
{
  if (!utils::is_double(text))
    lmp->error->all(FLERR, "fix cell/fluid: {} must be a number, got '{}'", name, text);
}

double osmotic_value(LAMMPS *lmp, const char *text, const std::string &what)
{
  require_number(lmp, text, "osmotic potential Pi" + what);
  const double Pi = utils::numeric(FLERR, text, false, lmp);
  if (Pi > 0.0)
    lmp->error->all(FLERR,
                    "fix cell/fluid: osmotic potential Pi{} must be <= 0 (water potential), got {}",
                    what, Pi);
  CellMech::require_magnitude(lmp, "fix cell/fluid", "osmotic potential Pi", Pi);
  return Pi;
}

double conductivity_value(LAMMPS *lmp, const char *text, const std::string &what)
{
  require_number(lmp, text, "hydraulic conductivity Lp" + what);
  const double Lp = utils::numeric(FLERR, text, false, lmp);
  if (Lp < 0.0)
    lmp->error->all(FLERR, "fix cell/fluid: hydraulic conductivity Lp{} must be >= 0, got {}", what,
                    Lp);
  CellMech::require_magnitude(lmp, "fix cell/fluid", "hydraulic conductivity Lp", Lp);
  return Lp;
}

tagint cell_id(LAMMPS *lmp, const char *text, const std::string &where)
{
  if (!utils::is_integer(text))
    lmp->error->all(FLERR,
                    "fix cell/fluid {}: the cell (molecule ID) must be an integer >= 1, got '{}'",
                    where, text);
  const tagint m = utils::tnumeric(FLERR, text, false, lmp);
  if (m < 1)
    lmp->error->all(FLERR, "fix cell/fluid {}: the cell (molecule ID) must be >= 1, got {}", where,
                    text);
  return m;
}
}    // namespace

namespace CellMech {

WaterSettings::WaterSettings(LAMMPS *_lmp) :
    expose_depth(EXPOSE_DEPTH_ANGSTROM * _lmp->force->angstrom), lmp(_lmp)
{
}

void WaterSettings::end_command()
{
  in_command = false;
  given.clear();
}

double WaterSettings::pi0_of(tagint id) const
{
  auto it = percell.find(id);
  return it != percell.end() && it->second.Pi ? *it->second.Pi : Pi;
}

double WaterSettings::lp_of(tagint id) const
{
  auto it = percell.find(id);
  return it != percell.end() && it->second.Lp ? *it->second.Lp : Lp;
}

bool WaterSettings::active() const
{
  bool any = Lp > 0.0 || external_flux();
  for (const auto &kv : percell) any = any || (kv.second.Lp && *kv.second.Lp > 0.0);
  return any;
}

// In the fix command a keyword other than cell and cells (which add up, cell by cell) may come
// once: a second one would silently replace the first (external psi, then external flux, ran with
// the flux only). fix_modify changes them between runs, so there the last one counts.
int WaterSettings::parse_keyword(int narg, char **arg)
{
  const int n = parse_one(narg, arg);
  const std::string key = arg[0];
  if (in_command && key != "cell" && key != "cells") {
    std::string words = key;
    for (int k = 1; k < n; k++) words += std::string(" ") + arg[k];
    auto it = given.find(key);
    if (it != given.end())
      lmp->error->all(FLERR,
                      "fix cell/fluid: keyword '{}' given twice, '{}' and '{}': give it once "
                      "(fix_modify changes it between runs)",
                      key, it->second, words);
    given[key] = words;
  }
  return n;
}

void WaterSettings::need(int narg, int n, const std::string &key, const char *form) const
{
  if (narg < n)
    lmp->error->all(FLERR, "fix cell/fluid: keyword '{}' needs {} argument(s): '{}', got {}", key,
                    n - 1, form, narg - 1);
}

int WaterSettings::parse_one(int narg, char **arg)
{
  const std::string key = arg[0];
  if (key == "Pi") {
    need(narg, 2, key, "Pi value");
    Pi = osmotic_value(lmp, arg[1], "");
    return 2;
  }
  if (key == "Lp") {
    need(narg, 2, key, "Lp value");
    Lp = conductivity_value(lmp, arg[1], "");
    return 2;
  }
  if (key == "cell") return parse_cell(narg, arg);
  if (key == "cells") {
    need(narg, 2, key, "cells file");
    return parse_cells_file(arg[1]);
  }
  if (key == "solute" || key == "exchange") {
    need(narg, 2, key, (key + " yes/no").c_str());
    (key == "solute" ? solute : exchange) = utils::logical(FLERR, arg[1], false, lmp);
    return 2;
  }
  if (key == "external") return parse_external(narg, arg);
  if (key == "exposed") return parse_exposed(narg, arg);
  if (key == "medium") return parse_medium(narg, arg);
  if (key == "share") return parse_share(narg, arg);
  lmp->error->all(FLERR,
                  "Unknown keyword '{}' for fix cell/fluid: expected Pi, Lp, cell, cells, solute, "
                  "exchange, external, exposed, medium or share",
                  key);
  return 0;
}

// share particle (Eq. 10 as written: every particle of a cell takes the same share) or share
// volume (Eq. W5: each in proportion to its volume m/rho, so that a cell whose particles differ in
// mass keeps one pressure while its water changes)
int WaterSettings::parse_share(int narg, char **arg)
{
  need(narg, 2, "share", "share particle/volume");
  if (strcmp(arg[1], "particle") == 0)
    share = SHARE_PARTICLE;
  else if (strcmp(arg[1], "volume") == 0)
    share = SHARE_VOLUME;
  else
    lmp->error->all(FLERR, "Fix cell/fluid share: expected particle or volume, got '{}'", arg[1]);
  return 2;
}

// cell M followed by Pi value and/or Lp value: unset ones stay the fix's own
int WaterSettings::parse_cell(int narg, char **arg)
{
  need(narg, 4, arg[0], "cell M Pi value Lp value");
  const tagint m = cell_id(lmp, arg[1], "cell");
  const std::string what = fmt::format(" of cell {}", m);
  auto it = percell.find(m);
  CellSetting v = it == percell.end() ? CellSetting() : it->second;
  int n = 2;
  while (n + 1 < narg && (strcmp(arg[n], "Pi") == 0 || strcmp(arg[n], "Lp") == 0)) {
    if (arg[n][0] == 'P')
      v.Pi = osmotic_value(lmp, arg[n + 1], what);
    else
      v.Lp = conductivity_value(lmp, arg[n + 1], what);
    n += 2;
  }
  if (n == 2)
    lmp->error->all(
        FLERR, "fix cell/fluid: keyword 'cell {}' expects 'Pi value' and/or 'Lp value', got '{}'",
        arg[1], arg[2]);
  percell[m] = v;
  return n;
}

// a file of lines 'M Pi Lp' (molecule ID, osmotic potential, conductivity); # starts a comment
int WaterSettings::parse_cells_file(const char *path)
{
  std::ifstream in(path);
  if (!in)
    lmp->error->all(FLERR, "fix cell/fluid cells: cannot open file '{}': {}", path,
                    utils::getsyserror());
  std::string line;
  int lineno = 0, entries = 0;
  while (std::getline(in, line)) {
    lineno++;
    line = utils::trim_comment(line);
    auto words = utils::split_words(line);
    if (words.empty()) continue;
    const std::string where = fmt::format("cells file '{}' line {}", path, lineno);
    if (words.size() != 3)
      lmp->error->all(FLERR, "fix cell/fluid {}: expected 'M Pi Lp' (3 numbers), got '{}'", where,
                      line);
    const std::string what = fmt::format(" in {}", where);
    const tagint m = cell_id(lmp, words[0].c_str(), where);
    percell[m] = {osmotic_value(lmp, words[1].c_str(), what),
                  conductivity_value(lmp, words[2].c_str(), what)};
    entries++;
  }
  // an empty file (the wrong one, or a generator that wrote nothing) would leave every cell at
  // the fix's Pi and Lp without a word
  if (entries == 0)
    lmp->error->all(FLERR,
                    "fix cell/fluid cells: file '{}' has no 'M Pi Lp' line ({} lines, all blank or "
                    "comments); give the cells' values or leave out the keyword",
                    path, lineno);
  return 2;
}

int WaterSettings::parse_external(int narg, char **arg)
{
  need(narg, 3, arg[0], "external psi value' or 'external flux value");
  if (strcmp(arg[1], "psi") == 0)
    external = EXT_PSI;
  else if (strcmp(arg[1], "flux") == 0)
    external = EXT_FLUX;
  else
    lmp->error->all(FLERR, "fix cell/fluid: keyword 'external' expects 'psi' or 'flux', got '{}'",
                    arg[1]);
  require_number(lmp, arg[2], fmt::format("the value of 'external {}'", arg[1]));
  ext_value = utils::numeric(FLERR, arg[2], false, lmp);
  if (ext_value != 0.0)
    CellMech::require_magnitude(lmp, "fix cell/fluid", "external value", ext_value);
  return 3;
}

int WaterSettings::parse_exposed(int narg, char **arg)
{
  need(narg, 2, arg[0], "exposed outside D' or 'exposed unglued");
  if (strcmp(arg[1], "unglued") == 0) {
    expose = EXPOSE_UNGLUED;
    return 2;
  }
  if (strcmp(arg[1], "outside") != 0)
    lmp->error->all(FLERR,
                    "fix cell/fluid: keyword 'exposed' expects 'outside D' or 'unglued', got '{}'",
                    arg[1]);
  need(narg, 3, arg[0], "exposed outside D");
  require_number(lmp, arg[2], "the distance D of 'exposed outside'");
  const double D = utils::numeric(FLERR, arg[2], false, lmp);
  if (D <= 0.0)
    lmp->error->all(
        FLERR, "fix cell/fluid: the distance D of 'exposed outside' must be > 0, got {}", arg[2]);
  CellMech::require_magnitude(lmp, "fix cell/fluid", "exposed distance", D);
  expose = EXPOSE_OUTSIDE;
  expose_depth = D;
  depth_given = true;
  return 3;
}

// What the outside is. Air, or a solution whose solutes cannot enter the wall (a large osmoticum
// such as PEG 6000): below zero turgor the protoplast stays on its wall and pulls it in
// (cytorrhysis), which pair cell/virtual's adhesion models. A solution that enters the wall
// (mannitol, sucrose, salts) fills the space the protoplast leaves (plasmolysis); the model has no
// outside fluid to fill it, so such a run would show a protoplasm torn from its wall into vacuum.
// The keyword exists so that a user who means a solution is told, not given that.
int WaterSettings::parse_medium(int narg, char **arg)
{
  need(narg, 2, arg[0], "medium air");
  if (strcmp(arg[1], "solution") == 0)
    lmp->error->all(
        FLERR,
        "fix cell/fluid: medium solution is not modelled: a solution that enters the wall fills "
        "the space the protoplast leaves (plasmolysis), and the package has no outside fluid to "
        "fill it. 'medium air' is air or a solution that cannot enter the wall (PEG), in which "
        "the protoplast holds on to its wall (cytorrhysis: pair_coeff ... cell/virtual ... "
        "adhere)");
  if (strcmp(arg[1], "air") != 0)
    lmp->error->all(FLERR,
                    "fix cell/fluid: keyword 'medium' expects 'air' (a solution that enters the "
                    "wall, plasmolysis, is not modelled), got '{}'",
                    arg[1]);
  return 2;
}

double WaterSettings::highest_pi0() const
{
  double hi = Pi;
  for (const auto &kv : percell)
    if (kv.second.Pi) hi = std::max(hi, *kv.second.Pi);
  return hi;
}

}    // namespace CellMech
