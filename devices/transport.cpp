// SPDX-License-Identifier: MIT
#include "transport.h"

namespace semhap {

Transport::Transport(DeviceModelPtr model) : m_model(std::move(model)) {}

Transport::~Transport() = default;

} // namespace semhap
