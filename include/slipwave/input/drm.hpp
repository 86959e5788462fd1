// Seismic input by the Domain Reduction Method (Bielak, Loukakis, Hisada & Yoshimura 2003,
// BSSA 93(2)): the free field u0(x, t) of the site without the scatterers is imposed as
// effective nodal forces on a layer one element thick, so that the interior Omega carries the
// total motion and the exterior only the scattered one, which the absorbing sides and base
// take away.
//
// Geometry. Omega is a set of elements (the cells at degree 1, the spectral elements at
// -element_degree p > 1): those whose centroid lies in -drm_box (2D xmin,xmax,ymin; 3D
// xmin,xmax,ymin,ymax,zmin; open upward), by default the mesh's bounding box shrunk by
// -drm_offset elements (default 2) on the sides and the base, or the elements of the regions
// -drm_regions a,b (Gmsh meshes). The boundary nodes b are the nodes shared by Omega and the
// other elements; the layer is the exterior elements touching a b node; the exterior nodes e
// are the layer's other nodes (at p > 1 every GLL node of a layer element off its faces on
// Omega). With the layer's element matrices only (Bielak et al. eq. 21):
//   P_b = -M_be u0''_e - K_be u0_e,   P_e = +M_eb u0''_b + K_eb u0_b.
// The mass is lumped (diagonal, GLL at p > 1), so M_be = M_eb = 0 and only the stiffness
// terms remain: the bulk operator's own element kernel applied to the b or e part of u0.
//
// Free field: a plane P, SV or SH wave (-drm_wave, -drm_incidence_angle from the vertical,
// -drm_azimuth of the horizontal direction of travel in 3D; in 2D a negative angle travels
// toward -x) in the horizontally layered site that the mesh itself holds: the materials of
// the cells that the vertical line through the mesh's lowest x (and y) corner, moved in by
// h/100, crosses (its "first column"), the deepest one taken as the half-space
// (physics/plane_wave_layered.hpp). Or a free field read from HDF5 (-drm_free_field_file,
// input/drm_field_file.hpp). Its velocity history -drm_stf ... (the
// TimeFunction options: wavelet or record) is that of the incident up-going wave at the
// reference point: the upstream edge of the DRM nodes, at the deepest DRM node or the top of
// the half-space if that is deeper; so no DRM node moves before t = 0 (causal).
// Damped sites (docs/drm.md, "Damped sites"): the free field uses each medium's complex
// density and moduli (physics/damped_medium.hpp); the forces use the layer's whole internal
// force F u0 = K u0 + beta K v0 - (constant-Q memory driven by K u0), the memory of each
// layer element's rows updated exactly as the solver's (physics::memoryUpdate) from the last
// committed step, v0 the free field's half-step velocity. The mass-proportional terms (alpha M,
// lumped) couple no b and e nodes. The base input (-input_wave) is refused with drm.
//
// Saturated sites (docs/drm.md, "Saturated sites"): the free field is the undrained one (each
// saturated layer with its undrained P modulus lambda + alpha^2 M, the excess pore pressure
// p0 = -alpha M eps_v per layer element, physics::undrainedPlaneWavePressure), and the forces
// are those of the u-p operator: the coupling and Darcy terms of the layer's saturated
// elements, which porous/pore_pressure_drm.hpp adds from DrmLayer (the pore pressure's
// matrices live on the floor above). Refused there: a free field from a file (it has no
// pressure) and damping (the solver damps the skeleton only, not alpha^2 M).
//
// The forces are external work booked as input (they go into Elastodynamics::f_input).
#pragma once
#include <petscts.h>

#include <string>
#include <vector>

#include "slipwave/fem/bulk_operator.hpp"
#include "slipwave/input/boundary_conditions.hpp"
#include "slipwave/medium/attenuation.hpp"
#include "slipwave/medium/materials.hpp"
#include "slipwave/physics/rayleigh_damping.hpp"

namespace slipwave::input {

struct Drm;

// A region's pore fluid as the undrained free field needs it: Biot's alpha and M; M = 0: dry.
struct DrmPoreFluid {
  double alpha = 0, M = 0;
};

// What the layer, the site and the forces are made from: the assembled problem's mesh, its
// regions' materials and damping and the bulk operator whose layer rows give the forces
// (problem/elastodynamics.cpp fills it from its Elastodynamics; the references stay valid
// for the run).
struct DrmSetting {
  MPI_Comm                                       comm;
  DM                                             dm;
  PetscInt                                       dim;
  const std::vector<std::string>                &regions; // region names, by region label value
  const std::vector<medium::RegionMaterialInfo> &materials;
  const fem::BulkOperator                       &bulk;
  physics::RayleighCoefficients                  rayleigh;
  const medium::Attenuation                     *attenuation; // constant-Q damping, or null
  InputWave                                      input_wave;  // the base input, refused with drm
  const std::vector<DrmPoreFluid>               *pore_fluid = nullptr; // per region, read by DrmCreate only; null: no saturated region
};

// The layer as the u-p terms need it (porous/pore_pressure_drm.hpp), at the time of the last
// DrmFreeFieldUpdate: per layer element its bulk element and, per element node, the index of
// its DRM node and whether it is a b node; u0 (dim per DRM node) and p0 (per element node,
// the element's own medium; zero in dry elements).
struct DrmLayer {
  const std::vector<PetscInt> &elements;
  const std::vector<size_t>   &element_node;
  const std::vector<char>     &element_node_is_b;
  const std::vector<double>   &u0, &p0;
  double                       time;
};
DrmLayer DrmLayerOf(const Drm *drm);
// Whether the free field carries an undrained pore pressure (some region is saturated).
bool DrmSaturated(const Drm *drm);

// Reads -input_method base|drm; for drm its options, the layer and the site. *drm stays null
// with base (the vertically incident base input of input/boundary_conditions.hpp).
PetscErrorCode DrmCreate(const DrmSetting &setting, Drm **drm);
PetscErrorCode DrmDestroy(Drm **drm);
// The free field u0 (and p0) at the layer's nodes at time t, kept until asked for another t.
// The free-field histories are synthesised at the first call, up to the TS's final time.
PetscErrorCode DrmFreeFieldUpdate(Drm *drm, const DrmSetting &setting, TS ts, PetscReal t);
// f += the effective forces at time t (global vector): the skeleton's; a saturated layer's
// coupling terms are porous::PorePressureDrmForce's.
PetscErrorCode DrmAddForce(Drm *drm, const DrmSetting &setting, TS ts, PetscReal t, Vec f);
// Lines for the run report (empty without DRM).
std::vector<std::string> DrmReport(const Drm *drm);
// The incident wave's highest frequency [Hz] (TimeFunction::topFrequency), for the resolution report.
double DrmTopFrequency(const Drm *drm);
// The trial of the last DrmAddForce (memory, u0) becomes the committed state (no-op without one).
void DrmCommit(Drm *drm);
// Committed state for checkpoints: [started, committed_time, u0 and memory of this rank].
std::vector<double> DrmState(const Drm *drm);
bool                DrmSetState(Drm *drm, const std::vector<double> &state);
PetscInt            DrmStateSize(const Drm *drm);

} // namespace slipwave::input
