// SPDX-License-Identifier: MIT
#include "link.h"

namespace semhap {

Link::~Link() = default;

} // namespace semhap
