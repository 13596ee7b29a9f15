#pragma once
// The Fast DDS peer's messages: Fast DDS's own DynamicTypes built at run time from the official
// ROS 2 field lists (../common/ros2_definitions.hpp), named as rmw names them, and DynamicData
// <-> JSON along those lists. Only fastdds_peer.cpp includes it.
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <fastrtps/types/DynamicDataFactory.h>
#include <fastrtps/types/DynamicTypeBuilderFactory.h>
#include <fastrtps/types/DynamicTypeBuilderPtr.h>
#include <nlohmann/json.hpp>

#include "../common/ros2_definitions.hpp"

namespace mechsim::ros2::peers::fast {

namespace types = eprosima::fastrtps::types;
using nlohmann::json;

struct FieldType {
  std::string base;  // int32, float64, string, pkg/Name, ...
  enum { Single, Array, Sequence } container = Single;
  std::uint32_t size = 0;
};

inline FieldType parse_type(const std::string& t) {
  FieldType f;
  const auto bracket = t.find('[');
  f.base = t.substr(0, bracket);
  if (bracket != std::string::npos) {
    const std::string inside = t.substr(bracket + 1, t.size() - bracket - 2);
    f.container = inside.empty() ? FieldType::Sequence : FieldType::Array;
    if (!inside.empty()) f.size = static_cast<std::uint32_t>(std::stoul(inside));
  }
  return f;
}

// The bound of every string type (see Types::primitive).
constexpr std::uint32_t kStringBound = 1u << 20;

class Types {
 public:
  explicit Types(const std::string& distro) : defs_(definitions(distro)) {}
  // The DynamicType of a message ("sensor_msgs/Image"), named as rmw names it on the wire.
  types::DynamicType_ptr get(const std::string& name) {
    if (auto it = built_.find(name); it != built_.end()) return it->second;
    auto* f = types::DynamicTypeBuilderFactory::get_instance();
    types::DynamicTypeBuilder_ptr b = f->create_struct_builder();
    // "pkg/Name" is a message (pkg::msg::dds_::Name_), "pkg/srv/Name_Request" a service's part.
    const auto slash = name.find('/');
    const bool srv = name.find("/srv/") != std::string::npos;
    const bool action = name.find("/action/") != std::string::npos;
    b->set_name(name.substr(0, slash) + (srv ? "::srv::dds_::" : action ? "::action::dds_::" : "::msg::dds_::") +
                name.substr(name.rfind('/') + 1) + "_");
    types::MemberId id = 0;
    for (const auto& [field, type] : defs_.at(name)) b->add_member(id++, field, element(parse_type(type)));
    return built_[name] = b->build();
  }
  const Fields& fields(const std::string& name) const { return defs_.at(name); }

 private:
  types::DynamicType_ptr primitive(const std::string& t) {
    auto* f = types::DynamicTypeBuilderFactory::get_instance();
    if (t == "int32") return f->create_int32_type();
    if (t == "int64") return f->create_int64_type();
    if (t == "uint64") return f->create_uint64_type();
    if (t == "uint16") return f->create_uint16_type();
    if (t == "int8") return f->create_char8_type();  // one byte on the wire
    if (t == "uint32") return f->create_uint32_type();
    if (t == "float32") return f->create_float32_type();
    if (t == "float64") return f->create_float64_type();
    if (t == "uint8") return f->create_byte_type();  // octet: the same byte on the wire
    if (t == "bool") return f->create_bool_type();
    // ROS 2 strings are unbounded (a description in /spawn_entity's xml or /robot_description is
    // kilobytes): DynamicData refuses to set a string past its type's bound (255 by default).
    if (t == "string") return f->create_string_type(kStringBound);
    return get(t);
  }
  types::DynamicType_ptr element(const FieldType& t) {
    auto* f = types::DynamicTypeBuilderFactory::get_instance();
    types::DynamicType_ptr e = primitive(t.base);
    if (t.container == FieldType::Array) return f->create_array_builder(e, {t.size})->build();
    if (t.container == FieldType::Sequence) return f->create_sequence_builder(e)->build();
    return e;
  }
  std::map<std::string, Fields> defs_;
  std::map<std::string, types::DynamicType_ptr> built_;
};

// ---- DynamicData <-> JSON, field by field along the definitions
inline json read_value(Types& t, types::DynamicData* d, types::MemberId id, const std::string& base) {
  if (base == "int32") return d->get_int32_value(id);
  if (base == "int64") return d->get_int64_value(id);
  if (base == "uint64") return d->get_uint64_value(id);
  if (base == "uint16") return d->get_uint16_value(id);
  if (base == "int8") return static_cast<int>(static_cast<signed char>(d->get_char8_value(id)));
  if (base == "uint32") return d->get_uint32_value(id);
  if (base == "float32") return d->get_float32_value(id);
  if (base == "float64") return d->get_float64_value(id);
  if (base == "uint8") return d->get_byte_value(id);
  if (base == "bool") return d->get_bool_value(id);
  if (base == "string") return d->get_string_value(id);
  types::DynamicData* nested = d->loan_value(id);
  json out = json::object();
  types::MemberId k = 0;
  for (const auto& [field, type] : t.fields(base)) {
    const FieldType ft = parse_type(type);
    if (ft.container == FieldType::Single) {
      out[field] = read_value(t, nested, k, ft.base);
    } else {
      types::DynamicData* seq = nested->loan_value(k);
      json items = json::array();
      for (std::uint32_t i = 0; i < seq->get_item_count(); ++i) items.push_back(read_value(t, seq, i, ft.base));
      nested->return_loaned_value(seq);
      out[field] = items;
    }
    ++k;
  }
  d->return_loaned_value(nested);
  return out;
}

inline json read_message(Types& t, types::DynamicData* d, const std::string& name) {
  json out = json::object();
  types::MemberId k = 0;
  for (const auto& [field, type] : t.fields(name)) {
    const FieldType ft = parse_type(type);
    if (ft.container == FieldType::Single) {
      out[field] = read_value(t, d, k, ft.base);
    } else {
      types::DynamicData* seq = d->loan_value(k);
      json items = json::array();
      for (std::uint32_t i = 0; i < seq->get_item_count(); ++i) items.push_back(read_value(t, seq, i, ft.base));
      d->return_loaned_value(seq);
      out[field] = items;
    }
    ++k;
  }
  return out;
}

inline void write_message(Types& t, types::DynamicData* d, const std::string& name, const json& v);

inline void write_value(Types& t, types::DynamicData* d, types::MemberId id, const std::string& base, const json& v) {
  if (base == "int32") d->set_int32_value(v.get<std::int32_t>(), id);
  else if (base == "int64") d->set_int64_value(v.get<std::int64_t>(), id);
  else if (base == "uint64") d->set_uint64_value(v.get<std::uint64_t>(), id);
  else if (base == "uint16") d->set_uint16_value(v.get<std::uint16_t>(), id);
  else if (base == "int8") d->set_char8_value(static_cast<char>(v.get<int>()), id);
  else if (base == "uint32") d->set_uint32_value(v.get<std::uint32_t>(), id);
  else if (base == "float32") d->set_float32_value(v.get<float>(), id);
  else if (base == "float64") d->set_float64_value(v.get<double>(), id);
  else if (base == "string") d->set_string_value(v.get<std::string>(), id);
  else if (base == "bool") d->set_bool_value(v.get<bool>(), id);
  else if (base == "uint8") d->set_byte_value(v.get<std::uint8_t>(), id);
  else {
    types::DynamicData* nested = d->loan_value(id);
    write_message(t, nested, base, v);
    d->return_loaned_value(nested);
  }
}

inline void write_message(Types& t, types::DynamicData* d, const std::string& name, const json& v) {
  types::MemberId k = 0;
  for (const auto& [field, type] : t.fields(name)) {
    const FieldType ft = parse_type(type);
    if (v.contains(field)) {
      if (ft.container == FieldType::Single) {
        write_value(t, d, k, ft.base, v[field]);
      } else if (ft.container == FieldType::Array) {
        types::DynamicData* arr = d->loan_value(k);
        for (std::uint32_t i = 0; i < ft.size && i < v[field].size(); ++i) write_value(t, arr, i, ft.base, v[field][i]);
        d->return_loaned_value(arr);
      } else if (ft.container == FieldType::Sequence) {
        types::DynamicData* seq = d->loan_value(k);
        for (const json& item : v[field]) {
          types::MemberId index = 0;
          if (ft.base == "float64") seq->insert_float64_value(item.get<double>(), index);
          else if (ft.base == "string") seq->insert_string_value(item.get<std::string>(), index);
          else if (ft.base == "int64") seq->insert_int64_value(item.get<std::int64_t>(), index);
          else if (ft.base == "bool") seq->insert_bool_value(item.get<bool>(), index);
          else if (ft.base == "uint8") seq->insert_byte_value(item.get<std::uint8_t>(), index);
          else {
            types::DynamicData* element = types::DynamicDataFactory::get_instance()->create_data(t.get(ft.base));
            write_message(t, element, ft.base, item);
            seq->insert_complex_value(element, index);
          }
        }
        d->return_loaned_value(seq);
      }
    }
    ++k;
  }
}

}  // namespace mechsim::ros2::peers::fast
