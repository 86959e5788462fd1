// Names of the DMPlex labels the mesh layer puts on the mesh, in one small header so the
// layers that read a label (fem, interface split, boundary faces) need not pull in the mesh
// builder.
#pragma once

namespace slipwave::mesh {

// Every cell; value = index of its region in MeshDescription::regions.
inline constexpr char kRegionLabel[] = "region";

// Spectral elements of degree p > 1 (meshing/spectral_subdivision.hpp): every GLL sub-cell;
// value = its lexicographic position in its element (x fastest), 0..p^dim-1. Which element
// follows from the topology (spectral_layout.hpp); a label value per element would make
// DMPlex's labels slow (DMLabelGetValue searches every value).
inline constexpr char kSpectralPositionLabel[] = "spectral_position";

} // namespace slipwave::mesh
