// Names of the DMPlex labels the mesh layer puts on the mesh, in one small header so the
// layers that read a label (fem, interface split, boundary faces) need not pull in the mesh
// builder.
#pragma once

namespace slipwave::mesh {

// Every cell; value = index of its region in MeshDescription::regions.
inline constexpr char kRegionLabel[] = "region";

// Spectral elements of degree p > 1 (mesh/spectral_subdivision.hpp): every GLL sub-cell;
// value = number of its element (the parent cell in the serial mesh before subdivision).
inline constexpr char kSpectralElementLabel[] = "spectral_element";
// Every GLL sub-cell; value = its lexicographic position in the element (x fastest), 0..p^dim-1.
inline constexpr char kSpectralPositionLabel[] = "spectral_position";

} // namespace slipwave::mesh
