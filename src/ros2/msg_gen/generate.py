#!/usr/bin/python3
"""ROS 2 .msg definitions -> C++ structs with XCDR1 (plain CDR, final) serialisation.

Run by src/ros2/CMakeLists.txt at build time with /usr/bin/python3 (no ROS 2 on the machine: the
generator is mechsim's own, the standard library only). Inputs are the definition sets under
src/ros2/msgs/: `common` (the same in every distro) and one folder per distro whose types differ
(humble, jazzy: rmw_dds_common's Gid is 24 bytes in Humble, 16 from Iron on). A type of a distro
set resolves its dependencies in that set first, then in `common`.

Outputs, under OUT/mechsim_ros2_msgs/:
  [<set>/]<pkg>.hpp    one struct per message (namespace mechsim::ros2[::<set>]::<pkg>::msg), its
                       constants, and MessageTraits (ROS and DDS names, REP-2016 type hash)
  [<set>/]<pkg>.cpp    cdr_write / cdr_read / cdr_size for each struct (fastcdr primitives; sequence
                       lengths checked against the bytes left before anything is allocated)
  type_table.hpp       every generated type with its hash (tests iterate it)

How .msg maps to the wire (the rosidl .msg -> IDL mapping, then XCDR1): bool -> boolean (1 byte),
byte -> octet, char -> uint8, float32/64 -> float/double, string<=N -> bounded string (same wire
form), T[N] -> array (no length), T[] and T[<=N] -> sequence (uint32 length). A message without
fields gets rosidl's `uint8 structure_needs_at_least_one_member`, on the wire and in the hash.

Type hash (RIHS01, REP-2016 as rosidl_generator_type_description computes it): the type and every
type it references (sorted by name) as {type_name, fields: [{name, type: {type_id, capacity,
string_capacity, nested_type_name}}]}, JSON with ', ' and ': ' separators, SHA-256.

Usage: generate.py --out DIR --set NAME=DIR [--set NAME=DIR ...]   (the first set is `common`)
"""

import argparse
import hashlib
import json
import os
import re
import sys

PRIMITIVES = {
    # msg type: (C++ type, IDL name for the hash, size in bytes)
    'bool': ('bool', 'boolean', 1),
    'byte': ('std::uint8_t', 'octet', 1),
    'char': ('std::uint8_t', 'uint8', 1),
    'int8': ('std::int8_t', 'int8', 1),
    'uint8': ('std::uint8_t', 'uint8', 1),
    'int16': ('std::int16_t', 'int16', 2),
    'uint16': ('std::uint16_t', 'uint16', 2),
    'int32': ('std::int32_t', 'int32', 4),
    'uint32': ('std::uint32_t', 'uint32', 4),
    'int64': ('std::int64_t', 'int64', 8),
    'uint64': ('std::uint64_t', 'uint64', 8),
    'float32': ('float', 'float', 4),
    'float64': ('double', 'double', 8),
}

# type_description_interfaces/msg/FieldType.msg
FIELD_TYPE_IDS = {
    'nested': 1, 'int8': 2, 'uint8': 3, 'int16': 4, 'uint16': 5, 'int32': 6, 'uint32': 7,
    'int64': 8, 'uint64': 9, 'float': 10, 'double': 11, 'char': 13, 'boolean': 15, 'octet': 16,
    'string': 17, 'wstring': 18, 'bounded_string': 21,
}
ARRAY_OFFSET, BOUNDED_SEQUENCE_OFFSET, UNBOUNDED_SEQUENCE_OFFSET = 48, 96, 144


class DefinitionError(Exception):
    pass


class Field:
    def __init__(self, name, base, string_bound, container, size, default):
        self.name = name
        self.base = base                  # primitive name, 'string', or 'pkg/Name'
        self.string_bound = string_bound  # 0: unbounded
        self.container = container        # None, 'array', 'bounded', 'sequence'
        self.size = size                  # array length or sequence bound
        self.default = default

    def nested(self):
        return '/' in self.base


class Constant:
    def __init__(self, name, base, value):
        self.name, self.base, self.value = name, base, value


class MsgType:
    def __init__(self, pkg, name, set_name, path, sub='msg'):
        self.pkg, self.name, self.set_name, self.path, self.sub = pkg, name, set_name, path, sub
        self.fields, self.constants = [], []
        self.service = None  # a service's request/response: the service's name

    def full(self):
        return self.pkg + '/' + self.name


TYPE_RE = re.compile(r'^([A-Za-z0-9_/]+?)(<=(\d+))?(\[(<=)?(\d*)\])?$')


def parse_msg(path, pkg, name, set_name, lines=None, first_line=1, sub='msg'):
    msg = MsgType(pkg, name, set_name, path, sub)
    if lines is None:
        with open(path, encoding='utf-8') as f:
            lines = f.read().splitlines()
    for number, raw in enumerate(lines, first_line):
        line = raw.split('#', 1)[0].strip() if '"' not in raw and "'" not in raw else raw.strip()
        if not line or line.startswith('#'):
            continue
        where = '%s:%d' % (path, number)
        type_token, _, rest = line.partition(' ')
        rest = rest.strip()
        m = TYPE_RE.match(type_token)
        if not m or not rest:
            raise DefinitionError('%s: cannot read "%s"' % (where, raw))
        base, string_bound = m.group(1), int(m.group(3) or 0)
        container, size = None, 0
        if m.group(4):
            if m.group(5):
                container, size = 'bounded', int(m.group(6))
            elif m.group(6):
                container, size = 'array', int(m.group(6))
            else:
                container = 'sequence'
        if string_bound and base not in ('string', 'wstring'):
            raise DefinitionError('%s: only strings take a bound (<=N)' % where)
        if base not in PRIMITIVES and base != 'string':
            if base == 'wstring':
                raise DefinitionError('%s: wstring is not supported' % where)
            if '/' not in base:
                base = pkg + '/' + base
        constant = re.match(r'^([A-Za-z][A-Za-z0-9_]*)\s*=\s*(.*)$', rest)
        if constant:
            msg.constants.append(Constant(constant.group(1), base, constant.group(2).strip()))
            continue
        fname, _, default = rest.partition(' ')
        if not re.match(r'^[a-z][a-z0-9_]*$', fname):
            raise DefinitionError('%s: field name "%s" is not a ROS 2 field name' % (where, fname))
        msg.fields.append(Field(fname, base, string_bound, container, size, default.strip() or None))
    if not msg.fields:
        msg.fields.append(Field('structure_needs_at_least_one_member', 'uint8', 0, None, 0, None))
    return msg


def load_set(set_name, root):
    types = {}
    for pkg in sorted(os.listdir(root)):
        msg_dir = os.path.join(root, pkg, 'msg')
        for entry in sorted(os.listdir(msg_dir)) if os.path.isdir(msg_dir) else []:
            if entry.endswith('.msg'):
                t = parse_msg(os.path.join(msg_dir, entry), pkg, entry[:-4], set_name)
                types[t.full()] = t
        # A service: its request and response messages, <Name>_Request and <Name>_Response in
        # <pkg>/srv (rosidl's names), split at the '---' line.
        srv_dir = os.path.join(root, pkg, 'srv')
        for entry in sorted(os.listdir(srv_dir)) if os.path.isdir(srv_dir) else []:
            if not entry.endswith('.srv'):
                continue
            path = os.path.join(srv_dir, entry)
            with open(path, encoding='utf-8') as f:
                lines = f.read().splitlines()
            split = [i for i, l in enumerate(lines) if l.strip() == '---']
            if len(split) != 1:
                raise DefinitionError('%s: a service has one \'---\' line' % path)
            name = entry[:-4]
            for part, (body, first) in (('Request', (lines[:split[0]], 1)), ('Response', (lines[split[0] + 1:], split[0] + 2))):
                t = parse_msg(path, pkg, name + '_' + part, set_name, body, first, 'srv')
                t.service = name
                types[t.full()] = t
        # An action (rosidl's action -> messages and services mapping): <Name>_Goal, _Result,
        # _Feedback; the services <Name>_SendGoal {goal_id, goal} -> {accepted, stamp} and
        # <Name>_GetResult {goal_id} -> {status, result}; the topic message <Name>_FeedbackMessage
        # {goal_id, feedback}; all in <pkg>/action.
        action_dir = os.path.join(root, pkg, 'action')
        for entry in sorted(os.listdir(action_dir)) if os.path.isdir(action_dir) else []:
            if not entry.endswith('.action'):
                continue
            path = os.path.join(action_dir, entry)
            with open(path, encoding='utf-8') as f:
                lines = f.read().splitlines()
            split = [i for i, l in enumerate(lines) if l.strip() == '---']
            if len(split) != 2:
                raise DefinitionError('%s: an action has two \'---\' lines' % path)
            name = entry[:-7]
            parts = (('Goal', lines[:split[0]], 1), ('Result', lines[split[0] + 1:split[1]], split[0] + 2),
                     ('Feedback', lines[split[1] + 1:], split[1] + 2))
            for part, body, first in parts:
                t = parse_msg(path, pkg, name + '_' + part, set_name, body, first, 'action')
                types[t.full()] = t
            uuid = 'unique_identifier_msgs/UUID goal_id'
            generated = (
                ('SendGoal_Request', [uuid, '%s_Goal goal' % name], name + '_SendGoal'),
                ('SendGoal_Response', ['bool accepted', 'builtin_interfaces/Time stamp'], name + '_SendGoal'),
                ('GetResult_Request', [uuid], name + '_GetResult'),
                ('GetResult_Response', ['int8 status', '%s_Result result' % name], name + '_GetResult'),
                ('FeedbackMessage', [uuid, '%s_Feedback feedback' % name], None),
            )
            for part, body, service in generated:
                t = parse_msg(path, pkg, name + '_' + part, set_name, body, 1, 'action')
                t.service = service
                types[t.full()] = t
    return types


class Universe:
    """Every set's types; lookups from a distro set fall back to `common`."""

    def __init__(self, sets):
        self.sets = sets  # [(name, {full: MsgType})], common first

    def find(self, full, set_name):
        for name, types in self.sets:
            if name == set_name and full in types:
                return types[full]
        for name, types in self.sets:
            if name == 'common' and full in types:
                return types[full]
        raise DefinitionError('unknown type %s (from set %s)' % (full, set_name))

    def resolve(self, msg, field):
        return self.find(field.base, msg.set_name)


# ---- type hash

def hash_field_type(field):
    if field.nested():
        kind = 'nested'
    elif field.base == 'string':
        kind = 'bounded_string' if field.string_bound else 'string'
    else:
        kind = PRIMITIVES[field.base][1]
    type_id = FIELD_TYPE_IDS[kind]
    if field.container == 'array':
        type_id += ARRAY_OFFSET
    elif field.container == 'bounded':
        type_id += BOUNDED_SEQUENCE_OFFSET
    elif field.container == 'sequence':
        type_id += UNBOUNDED_SEQUENCE_OFFSET
    return {
        'type_id': type_id,
        'capacity': field.size if field.container == 'array' else 0,
        'string_capacity': field.string_bound,
        'nested_type_name': hash_type_name(field.base) if field.nested() else '',
    }


def hash_type_name(full, sub='msg'):
    pkg, name = full.split('/')
    return pkg + '/' + sub + '/' + name


def individual_description(msg):
    return {'type_name': hash_type_name(msg.full(), msg.sub),
            'fields': [{'name': f.name, 'type': hash_field_type(f)} for f in msg.fields]}


def type_hash(universe, msg):
    referenced, queue = {}, [msg]
    while queue:
        current = queue.pop()
        for f in current.fields:
            if f.nested():
                dep = universe.resolve(current, f)
                key = hash_type_name(dep.full(), dep.sub)
                if key not in referenced:
                    referenced[key] = dep
                    queue.append(dep)
    description = {
        'type_description': individual_description(msg),
        'referenced_type_descriptions': [individual_description(referenced[k]) for k in sorted(referenced)],
    }
    text = json.dumps(description, skipkeys=False, ensure_ascii=True, check_circular=True,
                      allow_nan=False, indent=None, separators=(', ', ': '), sort_keys=False)
    return 'RIHS01_' + hashlib.sha256(text.encode('utf-8')).hexdigest()


# ---- C++

def namespace_of(set_name, pkg, sub='msg'):
    prefix = 'mechsim::ros2' if set_name == 'common' else 'mechsim::ros2::' + set_name
    return prefix + '::' + pkg + '::' + sub


def cxx_type_name(universe, msg, field):
    if field.nested():
        dep = universe.resolve(msg, field)
        return '::' + namespace_of(dep.set_name, dep.pkg, dep.sub) + '::' + dep.name
    if field.base == 'string':
        return 'std::string'
    return PRIMITIVES[field.base][0]


def cxx_member_type(universe, msg, field):
    element = cxx_type_name(universe, msg, field)
    if field.container == 'array':
        return 'std::array<%s, %d>' % (element, field.size)
    if field.container:
        return 'std::vector<%s>' % element
    return element


def cxx_literal(base, text):
    text = text.strip()
    if base == 'bool':
        return 'true' if text.lower() in ('true', '1') else 'false'
    if base == 'string':
        if len(text) >= 2 and text[0] == text[-1] and text[0] in '"\'':
            text = text[1:-1]
        return json.dumps(text)
    if base in ('float32', 'float64'):
        value = float(text)
        literal = repr(value)
        return literal + ('f' if base == 'float32' else '')
    return str(int(text, 0))


def cxx_default(field):
    if field.default is None:
        if field.container == 'array':
            return '{}'
        return ' = {}' if not field.container and not field.nested() and field.base != 'string' else ''
    if field.container:
        items = [x.strip() for x in field.default.strip('[]').split(',') if x.strip()]
        return '{' + ', '.join(cxx_literal(field.base, x) for x in items) + '}'
    return ' = ' + cxx_literal(field.base, field.default)


def min_size(universe, msg, cache):
    key = (msg.set_name, msg.full())
    if key in cache:
        return cache[key]
    total = 0
    for f in msg.fields:
        if f.container in ('sequence', 'bounded'):
            total += 4
            continue
        if f.nested():
            element = min_size(universe, universe.resolve(msg, f), cache)
        elif f.base == 'string':
            element = 4
        else:
            element = PRIMITIVES[f.base][2]
        total += element * (f.size if f.container == 'array' else 1)
    cache[key] = max(total, 1)
    return cache[key]


def element_min_size(universe, msg, field, cache):
    if field.nested():
        return min_size(universe, universe.resolve(msg, field), cache)
    if field.base == 'string':
        return 4
    return PRIMITIVES[field.base][2]


def write_field(universe, msg, f, out):
    m = 'm.' + f.name
    primitive = not f.nested() and f.base != 'string'
    if f.container == 'array':
        if primitive:
            out.append('  cdr.serializeArray(%s.data(), %s.size());' % (m, m))
        else:
            out.append('  for (const auto& e : %s) %s;' % (m, 'cdr_write(cdr, e)' if f.nested() else 'cdr << e'))
    elif f.container:
        if primitive:
            out.append('  cdr << %s;' % m)
        else:
            out.append('  cdr << static_cast<std::uint32_t>(%s.size());' % m)
            out.append('  for (const auto& e : %s) %s;' % (m, 'cdr_write(cdr, e)' if f.nested() else 'cdr << e'))
    elif f.nested():
        out.append('  cdr_write(cdr, %s);' % m)
    else:
        out.append('  cdr << %s;' % m)


def read_field(universe, msg, f, out, cache):
    m = 'm.' + f.name
    primitive = not f.nested() and f.base != 'string'
    element = 'cdr_read(in, e)' if f.nested() else 'in.cdr >> e'
    if f.container == 'array':
        if primitive:
            out.append('  in.cdr.deserializeArray(%s.data(), %s.size());' % (m, m))
        else:
            out.append('  for (auto& e : %s) %s;' % (m, element))
        return
    if f.container:
        if primitive and f.base != 'bool':
            out.append('  in.read_primitive_sequence(%s, %d);' % (m, f.size if f.container == 'bounded' else 0))
        else:
            out.append('  {')
            out.append('    const std::uint32_t count = in.read_count(%d, %d, "%s");' % (
                element_min_size(universe, msg, f, cache), f.size if f.container == 'bounded' else 0, f.name))
            out.append('    %s.resize(count);' % m)
            if f.base == 'bool':
                out.append('    for (std::uint32_t k = 0; k < count; ++k) { bool b = false; in.cdr >> b; %s[k] = b; }' % m)
            else:
                out.append('    for (auto& e : %s) %s;' % (m, element))
            out.append('  }')
        return
    if f.nested():
        out.append('  cdr_read(in, %s);' % m)
    elif f.base == 'string':
        out.append('  in.read_string(%s);' % m)
    else:
        out.append('  in.cdr >> %s;' % m)


def size_field(universe, msg, f, out):
    m = 'm.' + f.name
    if f.nested():
        one = 'p = cdr_size(e, p)'
    elif f.base == 'string':
        one = 'p = cdr_align(p, 4) + 4 + e.size() + 1'
    else:
        n = PRIMITIVES[f.base][2]
        if f.container == 'array':
            out.append('  p = cdr_align(p, %d) + %d * %s.size();' % (n, n, m))
            return
        if f.container:
            out.append('  p = cdr_align(p, 4) + 4;')
            out.append('  if (!%s.empty()) p = cdr_align(p, %d) + %d * %s.size();' % (m, n, n, m))
            return
        out.append('  p = cdr_align(p, %d) + %d;' % (n, n))
        return
    if f.container == 'array':
        out.append('  for (const auto& e : %s) %s;' % (m, one))
    elif f.container:
        out.append('  p = cdr_align(p, 4) + 4;')
        out.append('  for (const auto& e : %s) %s;' % (m, one))
    elif f.nested():
        out.append('  p = cdr_size(%s, p);' % m)
    else:
        out.append('  p = cdr_align(p, 4) + 4 + %s.size() + 1;' % m)


def header_path(set_name, pkg):
    return ('' if set_name == 'common' else set_name + '/') + pkg


def generate_package(universe, set_name, pkg, types, hashes, cache, out_dir):
    deps = set()
    for t in types:
        for f in t.fields:
            if f.nested():
                dep = universe.resolve(t, f)
                if (dep.set_name, dep.pkg) != (set_name, pkg):
                    deps.add(header_path(dep.set_name, dep.pkg))
    # Types of the package in dependency order.
    ordered, seen = [], set()

    def visit(t):
        if t.full() in seen:
            return
        seen.add(t.full())
        for f in t.fields:
            if f.nested():
                dep = universe.resolve(t, f)
                if (dep.set_name, dep.pkg) == (set_name, pkg):
                    visit(dep)
        ordered.append(t)

    for t in types:
        visit(t)
    h = ['// Generated by src/ros2/msg_gen/generate.py from src/ros2/msgs/%s/%s; do not edit.' % (set_name, pkg),
         '#pragma once', '', '#include <array>', '#include <cstddef>', '#include <cstdint>', '#include <string>',
         '#include <vector>', '', '#include "ros2/cdr.hpp"']
    for d in sorted(deps):
        h.append('#include <mechsim_ros2_msgs/%s.hpp>' % d)
    c = ['// Generated by src/ros2/msg_gen/generate.py; do not edit.',
         '#include <mechsim_ros2_msgs/%s.hpp>' % header_path(set_name, pkg), '', '#include <fastcdr/Cdr.h>']
    traits = ['', 'namespace mechsim::ros2 {', '']
    for sub in ('msg', 'srv', 'action'):
        group = [t for t in ordered if t.sub == sub]
        if not group:
            continue
        ns = namespace_of(set_name, pkg, sub)
        h += ['', 'namespace %s {' % ns, '']
        c += ['', 'namespace %s {' % ns, '']
        for t in group:
            h.append('// %s/%s/%s (%s)' % (t.pkg, t.sub, t.name, os.path.relpath(t.path, os.path.dirname(os.path.dirname(os.path.dirname(t.path))))))
            h.append('struct %s {' % t.name)
            for k in t.constants:
                ctype = 'const char*' if k.base == 'string' else PRIMITIVES[k.base][0]
                h.append('  static constexpr %s %s = %s;' % (ctype, k.name, cxx_literal(k.base, k.value)))
            for f in t.fields:
                h.append('  %s %s%s;' % (cxx_member_type(universe, t, f), f.name, cxx_default(f)))
            h.append('  bool operator==(const %s&) const = default;' % t.name)
            h.append('};')
            h.append('void cdr_write(eprosima::fastcdr::Cdr& cdr, const %s& m);' % t.name)
            h.append('void cdr_read(::mechsim::ros2::CdrReader& in, %s& m);' % t.name)
            h.append('std::size_t cdr_size(const %s& m, std::size_t p);' % t.name)
            h.append('')
            c.append('void cdr_write(eprosima::fastcdr::Cdr& cdr, const %s& m) {' % t.name)
            for f in t.fields:
                write_field(universe, t, f, c)
            c.append('}')
            c.append('')
            c.append('void cdr_read(::mechsim::ros2::CdrReader& in, %s& m) {' % t.name)
            for f in t.fields:
                read_field(universe, t, f, c, cache)
            c.append('}')
            c.append('')
            c.append('std::size_t cdr_size(const %s& m, std::size_t p) {' % t.name)
            c.append('  static_cast<void>(m);  // fixed-size types use only its type')
            for f in t.fields:
                size_field(universe, t, f, c)
            c.append('  return p;')
            c.append('}')
            c.append('')
            traits.append('template <>')
            traits.append('struct MessageTraits<::%s::%s> {' % (ns, t.name))
            traits.append('  static constexpr const char* ros_name = "%s/%s/%s";' % (t.pkg, t.sub, t.name))
            traits.append('  static constexpr const char* dds_name = "%s::%s::dds_::%s_";' % (t.pkg, t.sub, t.name))
            traits.append('  static constexpr const char* type_hash = "%s";' % hashes[(set_name, t.full())])
            traits.append('  static constexpr std::size_t min_size = %d;  // bytes, a lower bound' % min_size(universe, t, cache))
            traits.append('};')
        # A service: its two message types under one name (what a service server is made of).
        for t in group:
            if t.service is not None and t.name.endswith('_Request'):
                h.append('// The service %s/%s/%s.' % (t.pkg, t.sub, t.service))
                h.append('struct %s {' % t.service)
                h.append('  using Request = %s_Request;' % t.service)
                h.append('  using Response = %s_Response;' % t.service)
                h.append('  static constexpr const char* ros_name = "%s/%s/%s";' % (t.pkg, t.sub, t.service))
                h.append('};')
                h.append('')
        h.append('}  // namespace %s' % ns)
        c.append('}  // namespace %s' % ns)
    h += traits + ['', '}  // namespace mechsim::ros2', '']
    base = os.path.join(out_dir, 'mechsim_ros2_msgs', header_path(set_name, pkg))
    os.makedirs(os.path.dirname(base), exist_ok=True)
    write_if_changed(base + '.hpp', '\n'.join(h))
    write_if_changed(base + '.cpp', '\n'.join(c) + '\n')


def write_if_changed(path, text):
    if os.path.exists(path):
        with open(path, encoding='utf-8') as f:
            if f.read() == text:
                return
    with open(path, 'w', encoding='utf-8') as f:
        f.write(text)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--out', required=True)
    parser.add_argument('--set', action='append', required=True, help='NAME=DIR')
    parser.add_argument('--list', action='store_true', help='print the files it would write, one a line')
    args = parser.parse_args()
    sets = []
    for s in args.set:
        name, _, root = s.partition('=')
        sets.append((name, load_set(name, root)))
    if args.list:
        for name, types in sets:
            for pkg in sorted({t.pkg for t in types.values()}):
                base = os.path.join(args.out, 'mechsim_ros2_msgs', header_path(name, pkg))
                print(base + '.hpp')
                print(base + '.cpp')
        return 0
    universe = Universe(sets)
    hashes, cache, rows = {}, {}, []
    for name, types in sets:
        for full, t in sorted(types.items()):
            hashes[(name, full)] = type_hash(universe, t)
            rows.append('    {"%s", "%s/%s/%s", "%s"},' % (name, t.pkg, t.sub, t.name, hashes[(name, full)]))
    for name, types in sets:
        for pkg in sorted({t.pkg for t in types.values()}):
            generate_package(universe, name, pkg, [t for t in types.values() if t.pkg == pkg], hashes, cache, args.out)
    table = ['// Generated by src/ros2/msg_gen/generate.py; do not edit.', '#pragma once', '',
             'namespace mechsim::ros2 {', '',
             '// Every generated message type: its definition set (common, humble, jazzy), ROS name, RIHS01 hash.',
             'struct GeneratedType {', '  const char* set;', '  const char* ros_name;', '  const char* type_hash;', '};',
             '', 'inline constexpr GeneratedType kGeneratedTypes[] = {'] + rows + ['};', '', '}  // namespace mechsim::ros2', '']
    write_if_changed(os.path.join(args.out, 'mechsim_ros2_msgs', 'type_table.hpp'), '\n'.join(table))
    return 0


if __name__ == '__main__':
    try:
        sys.exit(main())
    except DefinitionError as e:
        print('generate.py: error: %s' % e, file=sys.stderr)
        sys.exit(1)
