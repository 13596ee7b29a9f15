// The bounded CDR reader of the generated message code (cdr.hpp).
#include "ros2/cdr.hpp"

#include <fastcdr/Cdr.h>

namespace mechsim::ros2 {

namespace {

template <class T>
void read_sequence(CdrReader& in, std::vector<T>& out, std::size_t bound) {
  const std::uint32_t count = in.read_count(sizeof(T), bound, "sequence");
  out.resize(count);
  if (count > 0) in.cdr.deserializeArray(out.data(), count);
}

}  // namespace

std::size_t CdrReader::remaining() const {
  const std::size_t used = cdr.getSerializedDataLength();
  return used < size ? size - used : 0;
}

std::uint32_t CdrReader::read_count(std::size_t element_min, std::size_t bound, const char* field) {
  std::uint32_t count = 0;
  cdr >> count;
  if (bound > 0 && count > bound) {
    throw CdrError(std::string("field '") + field + "': " + std::to_string(count) + " elements, bound " +
                   std::to_string(bound));
  }
  const std::size_t left = remaining();
  if (element_min > 0 && static_cast<std::size_t>(count) > left / element_min) {
    throw CdrError(std::string("field '") + field + "': " + std::to_string(count) +
                   " elements cannot fit in the " + std::to_string(left) + " bytes left");
  }
  return count;
}

void CdrReader::read_string(std::string& out) { cdr >> out; }

void CdrReader::read_primitive_sequence(std::vector<std::uint8_t>& out, std::size_t bound) { read_sequence(*this, out, bound); }
void CdrReader::read_primitive_sequence(std::vector<std::int8_t>& out, std::size_t bound) { read_sequence(*this, out, bound); }
void CdrReader::read_primitive_sequence(std::vector<std::uint16_t>& out, std::size_t bound) { read_sequence(*this, out, bound); }
void CdrReader::read_primitive_sequence(std::vector<std::int16_t>& out, std::size_t bound) { read_sequence(*this, out, bound); }
void CdrReader::read_primitive_sequence(std::vector<std::uint32_t>& out, std::size_t bound) { read_sequence(*this, out, bound); }
void CdrReader::read_primitive_sequence(std::vector<std::int32_t>& out, std::size_t bound) { read_sequence(*this, out, bound); }
void CdrReader::read_primitive_sequence(std::vector<std::uint64_t>& out, std::size_t bound) { read_sequence(*this, out, bound); }
void CdrReader::read_primitive_sequence(std::vector<std::int64_t>& out, std::size_t bound) { read_sequence(*this, out, bound); }
void CdrReader::read_primitive_sequence(std::vector<float>& out, std::size_t bound) { read_sequence(*this, out, bound); }
void CdrReader::read_primitive_sequence(std::vector<double>& out, std::size_t bound) { read_sequence(*this, out, bound); }

}  // namespace mechsim::ros2
