#pragma once
// Compiles MJCF text into a MuJoCo model for the sim tests (through MuJoCo's virtual file
// system); null if MuJoCo rejects it.

#include <mujoco/mujoco.h>

#include <cstring>
#include <string>

namespace graspecmf::sim::testing {

inline mjModel* load_model(const std::string& xml) {
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  mj_makeEmptyFileVFS(&vfs, "s.xml", static_cast<int>(xml.size()));
  std::memcpy(vfs.filedata[0], xml.data(), xml.size());
  char error[1000] = "";
  mjModel* model = mj_loadXML("s.xml", &vfs, error, sizeof(error));
  mj_deleteVFS(&vfs);
  return model;
}

}  // namespace graspecmf::sim::testing
