// A model's bearings as an OpenSees model (Tcl, OpenSees 3.8): what carries a design's bound
// models to a program whose building model the engineer already has. Each bearing law becomes the
// OpenSees element that reproduces it (docs/bearings.md), a zero-length element between two nodes
// of a three-dimensional model (ndm 3, ndf 6) with z up:
//
//   bhm2, elastoplastic, lead_rubber (no heating), hdr_bearing  elastomericBearingPlasticity: the
//       same bilinear loop (kInit = ke, qd = fs, alpha1 = kh / ke), coupled in plan
//   friction_pendulum   singleFPBearing with frictionModel Coulomb (mu) or VelDependent
//       (mu_slow, mu_fast, a): Reff = r, kInit = mu W / uy (mu_slow with mu(v))
//   triple_friction_pendulum (inner surfaces alike: r2 = r3, mu2 = mu3, d2 = d3)
//       TripleFrictionPendulum (L1 = r2, L2 = r1, L3 = r4, d1 = d2, d2 = d1, d3 = d4)
//   linear_spring       zeroLength with an Elastic material along x and y
//
// Every other law (the paper's BHM1, THM1, THM2, Bouc-Wen, degrading and play laws, dashpots, the
// double pendulum, a lead core that heats, an uncoupled pair) has no OpenSees element that
// reproduces it: the model is refused, naming the bearing, the component and its law. isolab
// models no vertical, torsional or rocking deformation of a bearing; the export gives them stiff
// Elastic materials, which the user may set before sourcing the file.
//
// The file defines `isolab_bearing NAME iNode jNode` (the bearing NAME's elements between the two
// nodes, returning their tags), one procedure per bearing type (isolab_type_...), and
// `isolab_sites`: each
// bearing's name, position in plan (0 0 in one direction), the weight W its pendulums carry (0
// for other laws: the axial load the model must apply for friction to act) and its procedure.
// Tags are drawn from `isolab_next_tag` (900001 unless set before sourcing).
#pragma once

#include <string>

#include "isolab/model/model_file.h"

namespace isolab::model {

struct OpenSeesExport {
  std::string tcl;      // the file's text; empty when refused
  std::string refused;  // why not: the bearing, its component and law (no file location)
};

// `title` heads the text (the bound and the model it came from). Refused for a bearing whose law
// has no OpenSees element, a pendulum with other components in parallel (OpenSees' pendulums
// take friction from their own axial force), a name that is not a Tcl word, and a model without
// bearings.
OpenSeesExport ExportToOpenSees(const ModelFile& model, const std::string& title);

}  // namespace isolab::model
