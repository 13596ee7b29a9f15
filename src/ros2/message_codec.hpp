#pragma once
// A ROS 2 message to and from its serialized form: the 4-byte encapsulation header (CDR little
// endian, as both ROS 2 middlewares write it; a big-endian sample is read as well) and the XCDR1
// body (cdr.hpp). Used by the DDS writers and readers (dds_topic.hpp) and by tests.

#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <vector>

#include <fastcdr/Cdr.h>
#include <fastcdr/FastBuffer.h>

#include "ros2/cdr.hpp"

namespace mechsim::ros2 {

// Bytes of the serialized sample, encapsulation header included.
template <class M>
std::size_t serialized_size(const M& message) {
  return 4 + cdr_size(message, 0);
}

// Writes the sample into `buffer` (at least serialized_size bytes); returns the bytes written.
template <class M>
std::size_t serialize_into(const M& message, char* buffer, std::size_t capacity) {
  eprosima::fastcdr::FastBuffer fast(buffer, capacity);
  eprosima::fastcdr::Cdr cdr(fast, eprosima::fastcdr::Cdr::DEFAULT_ENDIAN, eprosima::fastcdr::Cdr::DDS_CDR);
  cdr.serialize_encapsulation();
  cdr_write(cdr, message);
  return cdr.getSerializedDataLength();
}

template <class M>
std::vector<std::uint8_t> serialize(const M& message) {
  std::vector<std::uint8_t> bytes(serialized_size(message));
  bytes.resize(serialize_into(message, reinterpret_cast<char*>(bytes.data()), bytes.size()));
  return bytes;
}

// False with `error` saying what is wrong when the bytes are not a sample of M (too short, a
// length that cannot fit, a bool that is neither 0 nor 1, an unknown encapsulation). Never
// throws and allocates at most what the sample's own size allows.
template <class M>
bool deserialize(const std::uint8_t* data, std::size_t size, M& out, std::string* error) {
  if (size < 4) {
    if (error) *error = "sample of " + std::to_string(size) + " bytes has no encapsulation header";
    return false;
  }
  if (data[0] != 0 || (data[1] != 0 && data[1] != 1)) {
    if (error) {
      *error = "encapsulation " + std::to_string(data[0]) + "/" + std::to_string(data[1]) +
               " is not plain CDR (XCDR1, big or little endian): the writer's type is not a final ROS 2 message";
    }
    return false;
  }
  try {
    eprosima::fastcdr::FastBuffer fast(const_cast<char*>(reinterpret_cast<const char*>(data)), size);
    eprosima::fastcdr::Cdr cdr(fast, eprosima::fastcdr::Cdr::DEFAULT_ENDIAN, eprosima::fastcdr::Cdr::DDS_CDR);
    cdr.read_encapsulation();
    CdrReader in{cdr, size};
    cdr_read(in, out);
    return true;
  } catch (const std::exception& e) {
    if (error) *error = std::string(e.what()) + " (sample of " + std::to_string(size) + " bytes)";
  } catch (...) {
    if (error) *error = "unreadable sample of " + std::to_string(size) + " bytes";
  }
  return false;
}

}  // namespace mechsim::ros2
