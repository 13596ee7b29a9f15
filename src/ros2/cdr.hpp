#pragma once
// What the generated message code (msg_gen/generate.py, <mechsim_ros2_msgs/...>) builds on: the
// traits each message type specialises, and a bounded reader over eprosima::fastcdr::Cdr.
//
// A sample comes from the network, so its lengths are not trusted: every sequence length is
// checked against the bytes left in the sample (times the smallest size an element can have on
// the wire) before anything is allocated, and a bad one throws CdrError naming the field. The
// encoding is XCDR1 (plain CDR, "final" types), what rmw_fastrtps and rmw_cyclonedds put on the
// wire for ROS 2 messages: 4-byte encapsulation header, alignment relative to the byte after it.

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace eprosima::fastcdr {
class Cdr;
}

namespace mechsim::ros2 {

// Specialised by the generated headers for every message: ros_name ("std_msgs/msg/String"),
// dds_name ("std_msgs::msg::dds_::String_"), type_hash ("RIHS01_<64 hex>"), min_size (bytes).
template <class M>
struct MessageTraits;

struct CdrError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// `position` rounded up to a multiple of `alignment` (a power of two).
constexpr std::size_t cdr_align(std::size_t position, std::size_t alignment) {
  return (position + alignment - 1) & ~(alignment - 1);
}

// A Cdr positioned at the start of a sample's body, with the sample's size, so that sequence
// lengths can be checked before they are used.
struct CdrReader {
  eprosima::fastcdr::Cdr& cdr;
  std::size_t size;  // bytes of the whole sample, encapsulation header included

  std::size_t remaining() const;
  // A sequence length whose elements take at least `element_min` bytes each; `bound` > 0 is the
  // sequence's bound (T[<=N]). Throws CdrError naming `field` when it cannot fit.
  std::uint32_t read_count(std::size_t element_min, std::size_t bound, const char* field);
  void read_string(std::string& out);
  void read_primitive_sequence(std::vector<std::uint8_t>& out, std::size_t bound);
  void read_primitive_sequence(std::vector<std::int8_t>& out, std::size_t bound);
  void read_primitive_sequence(std::vector<std::uint16_t>& out, std::size_t bound);
  void read_primitive_sequence(std::vector<std::int16_t>& out, std::size_t bound);
  void read_primitive_sequence(std::vector<std::uint32_t>& out, std::size_t bound);
  void read_primitive_sequence(std::vector<std::int32_t>& out, std::size_t bound);
  void read_primitive_sequence(std::vector<std::uint64_t>& out, std::size_t bound);
  void read_primitive_sequence(std::vector<std::int64_t>& out, std::size_t bound);
  void read_primitive_sequence(std::vector<float>& out, std::size_t bound);
  void read_primitive_sequence(std::vector<double>& out, std::size_t bound);
};

}  // namespace mechsim::ros2
