// SPDX-License-Identifier: MIT
#pragma once

// RAII for MuJoCo's C handles. Only sim/ includes this (and <mujoco/mujoco.h>).

#include <mujoco/mujoco.h>

#include <memory>

namespace semhap {

struct MjModelDeleter
{
    void operator()(mjModel *model) const { mj_deleteModel(model); }
};
struct MjDataDeleter
{
    void operator()(mjData *data) const { mj_deleteData(data); }
};
/** mjVFS is a large fixed-size struct: keep it on the heap, delete its files with it. */
struct MjVfsDeleter
{
    void operator()(mjVFS *vfs) const
    {
        mj_deleteVFS(vfs);
        delete vfs;
    }
};

using MjModelPtr = std::unique_ptr<mjModel, MjModelDeleter>;
using MjDataPtr = std::unique_ptr<mjData, MjDataDeleter>;
using MjVfsPtr = std::unique_ptr<mjVFS, MjVfsDeleter>;

/**
 * Routes MuJoCo's errors and warnings to Qt's message handlers instead of MuJoCo's defaults
 * (which wait for Enter and write MUJOCO_LOG.TXT). Idempotent; every World calls it.
 */
void installMujocoHandlers();

} // namespace semhap
