#include "slipwave/io/interface_output.hpp"

#include <iterator>

#include "slipwave/core/log_events.hpp"

namespace slipwave::io {
namespace {

// Widths of the per-pair fields, in the order of InterfaceAssembler::pairFields (the
// saturated ones, pore_pressure and sigma_N_effective, scalars after these).
const int kWidths[] = {1, 3, 1, 3, 1, 1, 1, 1};

PetscErrorCode pairVector(MPI_Comm comm, PetscInt npairs, PetscInt width, Vec *v) {
  PetscFunctionBeginUser;
  PetscCall(VecCreate(comm, v));
  PetscCall(VecSetSizes(*v, PETSC_DECIDE, npairs * width));
  PetscCall(VecSetBlockSize(*v, width));
  PetscCall(VecSetFromOptions(*v));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode InterfaceOutput::Open(MPI_Comm comm, PetscInt dim, const interface::InterfaceAssembler &iface, const std::string &dir,
                                     const std::vector<std::pair<PetscInt, PetscReal>> *previous) {
  const meshing::InterfacePairs &pairs = iface.pairs();
  PetscFunctionBeginUser;
  dim_ = dim;
  PetscCall(pairVector(comm, pairs.n_global, dim, &geometry_));
  std::vector<PetscInt> rows(pairs.id.size() * dim);
  for (size_t p = 0; p < pairs.id.size(); ++p)
    for (PetscInt k = 0; k < dim; ++k) rows[p * dim + k] = pairs.id[p] * dim + k;
  PetscCall(VecSetValues(geometry_, (PetscInt)rows.size(), rows.data(), pairs.coords.data(), INSERT_VALUES));
  PetscCall(VecAssemblyBegin(geometry_));
  PetscCall(VecAssemblyEnd(geometry_));
  PetscCall(ISCreateGeneral(comm, (PetscInt)pairs.face_pairs.size(), pairs.face_pairs.data(), PETSC_COPY_VALUES, &topology_));
  PetscCall(ISSetBlockSize(topology_, pairs.nodes_per_face));
  names_ = iface.pairFieldNames();
  for (Vec *v : {&u_soil_, &u_relative_}) PetscCall(pairVector(comm, pairs.n_global, dim, v));
  for (size_t f = 0; f < names_.size(); ++f) {
    const int w = f < std::size(kWidths) ? kWidths[f] : 1;
    Vec       v;
    PetscCall(pairVector(comm, pairs.n_global, w, &v));
    fields_.push_back(v);
    widths_.push_back(w);
  }
  GridLayout grid;
  grid.name           = "interface_" + iface.spec().name;
  grid.dim            = (int)dim;
  grid.nodes_per_cell = (int)pairs.nodes_per_face;
  grid.cell_type      = dim == 2 ? "Polyline" : (pairs.nodes_per_face == 3 ? "Triangle" : "Quadrilateral");
  if (previous) {
    std::vector<FieldRef> layout = {{"displacement", Centering::Node, u_soil_}, {"displacement_relative", Centering::Node, u_relative_}};
    for (size_t f = 0; f < fields_.size(); ++f) layout.push_back({names_[f], Centering::Node, fields_[f]});
    PetscCall(writer_.Resume(comm, dir, grid, geometry_, topology_, *previous, layout));
  } else {
    PetscCall(writer_.Open(comm, dir, grid, geometry_, topology_));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceOutput::fill(const interface::InterfaceAssembler &iface, Vec u, const PetscScalar *base) {
  const meshing::InterfacePairs &pairs = iface.pairs();
  const PetscInt                 dim   = dim_;
  std::vector<double>         values;
  int                         per_pair;
  PetscFunctionBeginUser;
  PetscCall(iface.SoilSideDisplacement(u, &values));
  {
    std::vector<PetscInt> rows(values.size());
    std::vector<double>   relative(values.size());
    for (size_t p = 0; p < pairs.id.size(); ++p)
      for (PetscInt k = 0; k < dim; ++k) {
        rows[p * dim + k]     = pairs.id[p] * dim + k;
        relative[p * dim + k] = values[p * dim + k] - PetscRealPart(base[k]);
      }
    PetscCall(VecSetValues(u_soil_, (PetscInt)rows.size(), rows.data(), values.data(), INSERT_VALUES));
    PetscCall(VecSetValues(u_relative_, (PetscInt)rows.size(), rows.data(), relative.data(), INSERT_VALUES));
    for (Vec v : {u_soil_, u_relative_}) {
      PetscCall(VecAssemblyBegin(v));
      PetscCall(VecAssemblyEnd(v));
    }
  }
  iface.pairFields(&values, &per_pair);
  int offset = 0;
  for (size_t f = 0; f < fields_.size(); ++f) {
    const int             w = widths_[f];
    std::vector<PetscInt> rows(pairs.id.size() * w);
    std::vector<double>   vals(pairs.id.size() * w);
    for (size_t p = 0; p < pairs.id.size(); ++p)
      for (int k = 0; k < w; ++k) {
        rows[p * w + k] = pairs.id[p] * w + k;
        vals[p * w + k] = values[p * per_pair + offset + k];
      }
    PetscCall(VecSetValues(fields_[f], (PetscInt)rows.size(), rows.data(), vals.data(), INSERT_VALUES));
    PetscCall(VecAssemblyBegin(fields_[f]));
    PetscCall(VecAssemblyEnd(fields_[f]));
    offset += w;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceOutput::Write(const interface::InterfaceAssembler &iface, PetscInt step, PetscReal t, Vec u, const PetscScalar *base) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(core::event_output, 0, 0, 0, 0));
  PetscCall(fill(iface, u, base));
  std::vector<FieldRef> refs = {{"displacement", Centering::Node, u_soil_}, {"displacement_relative", Centering::Node, u_relative_}};
  for (size_t f = 0; f < fields_.size(); ++f) refs.push_back({names_[f], Centering::Node, fields_[f]});
  PetscCall(writer_.WriteStep(step, t, refs));
  PetscCall(PetscLogEventEnd(core::event_output, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceOutput::Close() {
  PetscFunctionBeginUser;
  PetscCall(writer_.Close());
  PetscCall(VecDestroy(&geometry_));
  PetscCall(VecDestroy(&u_soil_));
  PetscCall(VecDestroy(&u_relative_));
  PetscCall(ISDestroy(&topology_));
  for (Vec &v : fields_) PetscCall(VecDestroy(&v));
  fields_.clear();
  PetscFunctionReturn(0);
}

} // namespace slipwave::io
