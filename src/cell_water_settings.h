/* -*- c++ -*- ----------------------------------------------------------
   SPDX-License-Identifier: GPL-2.0-or-later
   cellmech: the water settings of fix cell/fluid, from its command and
   fix_modify: Pi and Lp of every cell and of single cells (keyword cell,
   a cells file), solutes kept (Eq. W1), exchange between cells (W2-W3)
   and the outside (W4). Not a style: fix cell/fluid reads its keywords
   through it, so its errors name fix cell/fluid.
------------------------------------------------------------------------- */

#ifndef CELLMECH_CELL_WATER_SETTINGS_H
#define CELLMECH_CELL_WATER_SETTINGS_H

#include "lmptype.h"

#include <map>
#include <optional>
#include <string>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace CellMech {

class WaterSettings {
 public:
  enum External { EXT_PSI, EXT_FLUX };
  enum Expose { EXPOSE_OUTSIDE, EXPOSE_UNGLUED };
  // how a cell's water flux is spread over its fluid particles: evenly (Eq. 10 as the paper writes
  // it, A_c L_p rho / N_f each), or in proportion to each particle's volume m/rho (Eq. W5)
  enum Share { SHARE_PARTICLE, SHARE_VOLUME };

  explicit WaterSettings(LAMMPS_NS::LAMMPS *);
  // one keyword and its arguments; returns how many words it took
  int parse_keyword(int narg, char **arg);
  // after the fix command: from now on (fix_modify) a keyword may be given again
  void end_command();

  // Pi0 and Lp of the cell with this molecule ID: its own, or the fix's where it has none
  double pi0_of(LAMMPS_NS::tagint id) const;
  double lp_of(LAMMPS_NS::tagint id) const;
  // water moves through some wall: a conductivity > 0 or a set flux
  bool active() const;
  bool external_flux() const { return external == EXT_FLUX && ext_value != 0.0; }
  bool exposed_outside() const { return exchange && expose == EXPOSE_OUTSIDE; }
  // the least negative osmotic potential Pi0 of any cell (the first to lose its turgor)
  double highest_pi0() const;

  double Pi = 0.0, Lp = 0.0;    // of every cell without a per-cell setting
  // a cell's own Pi and Lp (cell M, cells file); one left unset is the fix's
  struct CellSetting {
    std::optional<double> Pi, Lp;
  };
  std::map<LAMMPS_NS::tagint, CellSetting> percell;    // by molecule ID
  int solute = 0;                                      // 1: Pi W of each cell stays Pi0 W0 (Eq. W1)
  int exchange = 0;                  // 1: water crosses the glued walls between cells (Eq. W3)
  External external = EXT_PSI;       // exposed walls exchange with psi_ext, or lose a set flux
  double ext_value = 0.0;            // psi_ext or the flux per area
  Expose expose = EXPOSE_OUTSIDE;    // with exchange: neither glued nor faced, or not glued
  Share share = SHARE_PARTICLE;
  bool share_volume() const { return share == SHARE_VOLUME; }
  double expose_depth;         // EXPOSE_OUTSIDE: how far in front another wall hides a triangle
  bool depth_given = false;    // exposed outside D given (no default in units lj)

 private:
  LAMMPS_NS::LAMMPS *lmp;
  std::map<std::string, std::string> given;    // fix command: keyword -> its words, once each
  bool in_command = true;                      // parsing the fix command (not fix_modify)

  int parse_one(int narg, char **arg);
  int parse_cell(int narg, char **arg);
  int parse_cells_file(const char *path);
  int parse_external(int narg, char **arg);
  int parse_exposed(int narg, char **arg);
  int parse_medium(int narg, char **arg);
  int parse_share(int narg, char **arg);
  void need(int narg, int n, const std::string &key, const char *form) const;
};

}    // namespace CellMech

#endif
