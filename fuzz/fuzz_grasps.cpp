// Fuzzes the grasp-format decoders (formats/format_codecs.hpp): the first byte picks isaac_grasp
// YAML, ACRONYM JSON, plain JSON, GraspNet .npy or Contact-GraspNet .npz; the rest is the file.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "graspecmf/core/error.hpp"
#include "graspecmf/formats/format_codecs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace graspecmf::formats;
  if (size == 0) return 0;
  const std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    GraspSet grasps;
    switch (data[0] % 5) {
      case 0:
        grasps = decode_isaac_yaml(bytes, "fuzz", IsaacGripperFrame::automatic);
        break;
      case 1:
        grasps = decode_acronym_json(bytes, "fuzz");
        break;
      case 2:
        grasps = decode_plain_json(bytes, "fuzz");
        break;
      case 3:
        grasps = decode_graspnet_npy(bytes, "fuzz");
        break;
      default:
        grasps = decode_contact_graspnet_npz(bytes, "fuzz");
        break;
    }
    check_grasp_set(grasps, "fuzz");
  } catch (const graspecmf::Error&) {
    // The decoder refused the input with its one-line error: the expected outcome.
  }
  return 0;
}
