// Names of the DMPlex labels the mesh layer puts on the mesh, in one small header so the
// layers that read a label (fem, interface split, boundary faces) need not pull in the mesh
// builder.
#pragma once

namespace slipwave::mesh {

// Every cell; value = index of its region in MeshDescription::regions.
inline constexpr char kRegionLabel[] = "region";

} // namespace slipwave::mesh
