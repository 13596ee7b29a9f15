#pragma once
// JSON <-> XCDR1 (plain CDR, little endian, final types: what rmw_fastrtps and rmw_cyclonedds put
// on the wire for ROS 2 messages) along the field lists of ros2_definitions.hpp. The Cyclone DDS
// client serializes with it as rmw_cyclonedds_cpp does with its own serializer (rmw_cyclonedds'
// serdata.cpp: the middleware serializes ROS messages itself, Cyclone carries the bytes). Written
// for the peers from the CDR rules (OMG DDS-XTypes 1.3, 7.4.1 "Extended CDR Representation (XCDR1)"):
// each primitive aligned to its size counted from the first byte after the 4-byte encapsulation
// header; a string is a uint32 length counting its NUL, the bytes and the NUL; a sequence a
// uint32 length then its elements; an array only its elements. Nothing of mechsim's code.

#include <cstdint>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "ros2_definitions.hpp"

namespace mechsim::ros2::peers {

struct CdrType {
  std::string base;  // int32, string, pkg/Name, ...
  enum { Single, Array, Sequence } container = Single;
  std::uint32_t size = 0;
};

inline CdrType parse_cdr_type(const std::string& t) {
  CdrType f;
  const auto bracket = t.find('[');
  f.base = t.substr(0, bracket);
  if (bracket != std::string::npos) {
    const std::string inside = t.substr(bracket + 1, t.size() - bracket - 2);
    f.container = inside.empty() ? CdrType::Sequence : CdrType::Array;
    if (!inside.empty()) f.size = static_cast<std::uint32_t>(std::stoul(inside));
  }
  return f;
}

// Bytes of a primitive (0: not a primitive).
inline std::size_t primitive_size(const std::string& base) {
  static const std::map<std::string, std::size_t> sizes = {
      {"bool", 1},  {"int8", 1},   {"uint8", 1},  {"byte", 1},   {"char", 1},    {"int16", 2},   {"uint16", 2},
      {"int32", 4}, {"uint32", 4}, {"float32", 4}, {"int64", 8}, {"uint64", 8}, {"float64", 8}};
  const auto it = sizes.find(base);
  return it == sizes.end() ? 0 : it->second;
}

class CdrOut {
 public:
  CdrOut() : bytes_{0x00, 0x01, 0x00, 0x00} {}  // CDR_LE, no options
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }
  void align(std::size_t n) {
    while ((bytes_.size() - 4) % n != 0) bytes_.push_back(0);
  }
  template <class T>
  void put(T v) {
    align(sizeof(T));
    const auto* p = reinterpret_cast<const std::uint8_t*>(&v);
    bytes_.insert(bytes_.end(), p, p + sizeof(T));
  }
  void put_string(const std::string& s) {
    put<std::uint32_t>(static_cast<std::uint32_t>(s.size() + 1));
    bytes_.insert(bytes_.end(), s.begin(), s.end());
    bytes_.push_back(0);
  }

 private:
  std::vector<std::uint8_t> bytes_;
};

class CdrIn {
 public:
  // `data` starts with the 4-byte encapsulation header.
  CdrIn(const std::uint8_t* data, std::size_t size) : data_(data), size_(size), pos_(4) {
    if (size < 4) throw std::runtime_error("a sample of " + std::to_string(size) + " bytes has no encapsulation header");
    if (data[1] != 0x01) throw std::runtime_error("not little-endian plain CDR (encapsulation " + std::to_string(data[1]) + ")");
  }
  void align(std::size_t n) {
    while ((pos_ - 4) % n != 0) ++pos_;
  }
  template <class T>
  T get() {
    align(sizeof(T));
    need(sizeof(T));
    T v;
    std::memcpy(&v, data_ + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  std::string get_string() {
    const std::uint32_t n = get<std::uint32_t>();
    if (n == 0) throw std::runtime_error("a string of length 0 (no NUL)");
    need(n);
    std::string s(reinterpret_cast<const char*>(data_ + pos_), n - 1);
    pos_ += n;
    return s;
  }
  std::size_t left() const { return size_ - pos_; }

 private:
  void need(std::size_t n) const {
    if (pos_ + n > size_) throw std::runtime_error("the sample ends early");
  }
  const std::uint8_t* data_;
  std::size_t size_, pos_;
};

class CdrCodec {
 public:
  explicit CdrCodec(std::map<std::string, Fields> defs) : defs_(std::move(defs)) {}
  bool has(const std::string& type) const { return defs_.count(type) > 0; }

  // Missing JSON fields are zero, empty, or "".
  void encode(const std::string& type, const nlohmann::json& v, CdrOut& out) const {
    for (const auto& [field, t] : fields(type)) {
      const CdrType ft = parse_cdr_type(t);
      const nlohmann::json value = v.is_object() && v.contains(field) ? v[field] : nlohmann::json();
      if (ft.container == CdrType::Single) {
        encode_value(ft.base, value, out);
      } else {
        const std::size_t n = ft.container == CdrType::Array ? ft.size : (value.is_array() ? value.size() : 0);
        if (ft.container == CdrType::Sequence) out.put<std::uint32_t>(static_cast<std::uint32_t>(n));
        for (std::size_t i = 0; i < n; ++i)
          encode_value(ft.base, value.is_array() && i < value.size() ? value[i] : nlohmann::json(), out);
      }
    }
  }
  nlohmann::json decode(const std::string& type, CdrIn& in) const {
    nlohmann::json out = nlohmann::json::object();
    for (const auto& [field, t] : fields(type)) {
      const CdrType ft = parse_cdr_type(t);
      if (ft.container == CdrType::Single) {
        out[field] = decode_value(ft.base, in);
      } else {
        std::uint32_t n = ft.size;
        if (ft.container == CdrType::Sequence) {
          n = in.get<std::uint32_t>();
          if (n > in.left()) throw std::runtime_error("field '" + field + "': " + std::to_string(n) + " elements cannot fit");
        }
        nlohmann::json items = nlohmann::json::array();
        for (std::uint32_t i = 0; i < n; ++i) items.push_back(decode_value(ft.base, in));
        out[field] = items;
      }
    }
    return out;
  }

 private:
  const Fields& fields(const std::string& type) const {
    const auto it = defs_.find(type);
    if (it == defs_.end()) throw std::runtime_error("no definition of " + type);
    return it->second;
  }
  void encode_value(const std::string& base, const nlohmann::json& v, CdrOut& out) const {
    auto num = [&](auto zero) { return v.is_null() ? zero : v.get<decltype(zero)>(); };
    if (base == "bool") out.put<std::uint8_t>(v.is_null() ? 0 : (v.get<bool>() ? 1 : 0));
    else if (base == "int8") out.put<std::int8_t>(static_cast<std::int8_t>(num(0)));
    else if (base == "uint8" || base == "byte" || base == "char") out.put<std::uint8_t>(static_cast<std::uint8_t>(num(0u)));
    else if (base == "int16") out.put<std::int16_t>(static_cast<std::int16_t>(num(0)));
    else if (base == "uint16") out.put<std::uint16_t>(static_cast<std::uint16_t>(num(0u)));
    else if (base == "int32") out.put<std::int32_t>(num(std::int32_t{0}));
    else if (base == "uint32") out.put<std::uint32_t>(num(std::uint32_t{0}));
    else if (base == "int64") out.put<std::int64_t>(num(std::int64_t{0}));
    else if (base == "uint64") out.put<std::uint64_t>(num(std::uint64_t{0}));
    else if (base == "float32") out.put<float>(num(0.0f));
    else if (base == "float64") out.put<double>(num(0.0));
    else if (base == "string") out.put_string(v.is_null() ? std::string() : v.get<std::string>());
    else encode(base, v, out);
  }
  nlohmann::json decode_value(const std::string& base, CdrIn& in) const {
    if (base == "bool") return in.get<std::uint8_t>() != 0;
    if (base == "int8") return static_cast<int>(in.get<std::int8_t>());
    if (base == "uint8" || base == "byte" || base == "char") return static_cast<unsigned>(in.get<std::uint8_t>());
    if (base == "int16") return in.get<std::int16_t>();
    if (base == "uint16") return in.get<std::uint16_t>();
    if (base == "int32") return in.get<std::int32_t>();
    if (base == "uint32") return in.get<std::uint32_t>();
    if (base == "int64") return in.get<std::int64_t>();
    if (base == "uint64") return in.get<std::uint64_t>();
    if (base == "float32") return in.get<float>();
    if (base == "float64") return in.get<double>();
    if (base == "string") return in.get_string();
    return decode(base, in);
  }

  std::map<std::string, Fields> defs_;
};

}  // namespace mechsim::ros2::peers
