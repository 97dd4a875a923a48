#pragma once
// The three-layer element before the assembly speed-up (see the .cpp): the tests' reference.
#include "tirefem/element/three_layer_element.hpp"

namespace tirefem::reference {

ElementResponse three_layer_element(const NodeMatrix& reference, const NodeMatrix& current,
                                    const ElementSection& section, Kinematics kinematics,
                                    bool with_tangent = true);

}  // namespace tirefem::reference
