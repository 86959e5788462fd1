#include "slipwave/physics/mohr_coulomb_interface.hpp"

namespace slipwave::physics {

const char *interfaceStatusName(InterfaceStatus status) {
  switch (status) {
  case InterfaceStatus::Stick: return "stick";
  case InterfaceStatus::Slip: return "slip";
  case InterfaceStatus::Open: return "open";
  }
  return "unknown";
}

} // namespace slipwave::physics
