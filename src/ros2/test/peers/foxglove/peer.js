// A ROS 2 peer on @foxglove/ros2 (an independent TypeScript implementation of ROS 2 over RTPS,
// from npm) for mechsim's ROS 2 wire tests: it subscribes and decodes with foxglove's own copies
// of the official message definitions (@foxglove/rosmsg-msgs-common, per distro) and prints what
// it saw as JSON lines, in the same form as the Cyclone peer (../cyclone/cyclone_peer.c).
//
//   node peer.js --domain D --seconds S --distro humble|jazzy [--save-png FILE]
//                --sub TOPIC=KIND[:QOS] ...   KIND: clock tf tf_static joint_state laser image camera_info
//                                                  odometry imu string graph
//                                             QOS: be (best effort), vol (reliable volatile), tl
//
// @foxglove/ros2's RosNode.subscribe asks for reliable + transient local, always, which a volatile
// writer (rclcpp's default) or a best-effort one (sensor data) does not match; the peer makes its
// subscriptions itself, with the library's Subscription over its participant, asking for the QoS
// an rclcpp subscriber of that kind asks for.
"use strict";

const zlib = require("zlib");
const fs = require("fs");
const { RosNode, Subscription, rosTopicToDds, rosTypeToDds } = require("@foxglove/ros2");
const { UdpSocketNode } = require("@foxglove/ros2/nodejs");
const rtps = require("@foxglove/rtps");
const { parse } = require("@foxglove/rosmsg");
const { MessageReader } = require("@foxglove/rosmsg2-serialization");
const common = require("@foxglove/rosmsg-msgs-common");

const KINDS = {
  clock: { type: "rosgraph_msgs/msg/Clock", qos: "be" },           // rclcpp::ClockQoS
  tf: { type: "tf2_msgs/msg/TFMessage", qos: "vol" },              // tf2_ros::DynamicListenerQoS
  tf_static: { type: "tf2_msgs/msg/TFMessage", qos: "tl" },        // tf2_ros::StaticListenerQoS
  joint_state: { type: "sensor_msgs/msg/JointState", qos: "vol" },
  laser: { type: "sensor_msgs/msg/LaserScan", qos: "be" },         // rclcpp::SensorDataQoS
  image: { type: "sensor_msgs/msg/Image", qos: "be" },
  camera_info: { type: "sensor_msgs/msg/CameraInfo", qos: "be" },
  odometry: { type: "nav_msgs/msg/Odometry", qos: "vol" },
  imu: { type: "sensor_msgs/msg/Imu", qos: "be" },
  string: { type: "std_msgs/msg/String", qos: "tl" },              // robot_description
  graph: { type: "rmw_dds_common/msg/ParticipantEntitiesInfo", qos: "tl" },
};

// rmw_dds_common's graph message, from its official .msg files (not in msgs-common).
function graphDefinition(distro) {
  const gid = distro === "humble" ? 24 : 16;
  return parse(
    `Gid gid
NodeEntitiesInfo[] node_entities_info_seq
================================================================================
MSG: rmw_dds_common/Gid
char[${gid}] data
================================================================================
MSG: rmw_dds_common/NodeEntitiesInfo
string<=256 node_namespace
string<=256 node_name
Gid[] reader_gid_seq
Gid[] writer_gid_seq`,
    { ros2: true },
  );
}

// The root type's definition and every type it uses, from foxglove's copies of the definitions.
function definitionOf(distro, rosType) {
  if (rosType.startsWith("rmw_dds_common/")) return graphDefinition(distro);
  const table = distro === "humble" ? common.ros2humble : common.ros2jazzy;
  const key = rosType.replace("/msg/", "/");
  const out = [];
  const seen = new Set();
  const visit = (name, root) => {
    if (seen.has(name)) return;
    seen.add(name);
    const def = table[name];
    if (def == undefined) throw new Error(`no definition of ${name} for ${distro}`);
    out.push(root ? { ...def, name: undefined } : def);
    for (const f of def.definitions) if (f.isComplex === true) visit(f.type, false);
  };
  visit(key, true);
  return out;
}

function parseArgs(argv) {
  const a = { domain: 0, seconds: 5, distro: "jazzy", subs: [], png: undefined };
  for (let i = 2; i < argv.length; ++i) {
    const v = argv[i + 1];
    if (argv[i] === "--domain") a.domain = Number(argv[++i]);
    else if (argv[i] === "--seconds") a.seconds = Number(argv[++i]);
    else if (argv[i] === "--distro") a.distro = argv[++i];
    else if (argv[i] === "--save-png") a.png = argv[++i];
    else if (argv[i] === "--debug") a.debug = true;
    else if (argv[i] === "--sub" && v != undefined) {
      const [topic, spec] = argv[++i].split("=");
      const [kind, qos] = spec.split(":");
      if (KINDS[kind] == undefined) throw new Error(`unknown kind ${kind}`);
      a.subs.push({ topic, kind, qos: qos ?? KINDS[kind].qos });
    } else throw new Error(`unknown argument ${argv[i]}`);
  }
  return a;
}

const sec = (t) => ({ sec: t.sec, nanosec: t.nsec ?? t.nanosec });
const header = (h) => ({ stamp: sec(h.stamp), frame_id: h.frame_id });
const xyz = (v) => [v.x, v.y, v.z];
const num = (v) => (Number.isFinite(v) ? v : String(v));

let savePng;
function describe(kind, m) {
  switch (kind) {
    case "clock":
      return { clock: sec(m.clock) };
    case "tf":
    case "tf_static":
      return {
        count: m.transforms.length,
        transforms: m.transforms.map((t) => ({
          ...header(t.header),
          child: t.child_frame_id,
          t: xyz(t.transform.translation),
          q: [t.transform.rotation.x, t.transform.rotation.y, t.transform.rotation.z, t.transform.rotation.w],
        })),
      };
    case "joint_state":
      return { ...header(m.header), name: m.name, position: Array.from(m.position), velocity: Array.from(m.velocity) };
    case "laser": {
      const finite = Array.from(m.ranges).filter((r) => Number.isFinite(r));
      return {
        ...header(m.header),
        angle_min: m.angle_min,
        angle_max: m.angle_max,
        angle_increment: m.angle_increment,
        range_min: m.range_min,
        range_max: m.range_max,
        ranges: m.ranges.length,
        finite: finite.length,
        nearest: finite.length ? Math.min(...finite) : -1,
        farthest: finite.length ? Math.max(...finite) : -1,
      };
    }
    case "image": {
      let sum = 0;
      for (const b of m.data) sum += b;
      if (savePng && m.encoding === "rgb8" && m.data.length === m.height * m.step) savePng(m);
      return { ...header(m.header), height: m.height, width: m.width, encoding: m.encoding, step: m.step,
               bytes: m.data.length, mean: m.data.length ? sum / m.data.length : 0 };
    }
    case "camera_info":
      return { ...header(m.header), height: m.height, width: m.width, distortion_model: m.distortion_model,
               d: Array.from(m.d), k: Array.from(m.k), p: Array.from(m.p) };
    case "odometry":
      return { ...header(m.header), child_frame_id: m.child_frame_id, position: xyz(m.pose.pose.position),
               orientation: [m.pose.pose.orientation.x, m.pose.pose.orientation.y, m.pose.pose.orientation.z,
                             m.pose.pose.orientation.w],
               linear: xyz(m.twist.twist.linear), angular: xyz(m.twist.twist.angular) };
    case "imu":
      return { ...header(m.header), orientation: [m.orientation.x, m.orientation.y, m.orientation.z, m.orientation.w],
               linear_acceleration: xyz(m.linear_acceleration) };
    case "string":
      return { length: m.data.length, head: m.data.slice(0, 80) };
    case "graph":
      return { gid_size: m.gid.data.length, gid: Buffer.from(m.gid.data).toString("hex"),
               nodes: m.node_entities_info_seq.map((n) => ({ namespace: n.node_namespace, name: n.node_name,
                                                             readers: n.reader_gid_seq.length,
                                                             writers: n.writer_gid_seq.length })) };
    default:
      return {};
  }
}

// A PNG (RGB, 8 bits) of an rgb8 image, with Node's own zlib: what the peer saw.
function pngOf(m) {
  const crcTable = Array.from({ length: 256 }, (_, n) => {
    let c = n;
    for (let k = 0; k < 8; ++k) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
    return c >>> 0;
  });
  const crc = (buf) => {
    let c = 0xffffffff;
    for (const b of buf) c = crcTable[(c ^ b) & 0xff] ^ (c >>> 8);
    return (c ^ 0xffffffff) >>> 0;
  };
  const chunk = (type, data) => {
    const len = Buffer.alloc(4);
    len.writeUInt32BE(data.length);
    const body = Buffer.concat([Buffer.from(type, "ascii"), data]);
    const c = Buffer.alloc(4);
    c.writeUInt32BE(crc(body));
    return Buffer.concat([len, body, c]);
  };
  const ihdr = Buffer.alloc(13);
  ihdr.writeUInt32BE(m.width, 0);
  ihdr.writeUInt32BE(m.height, 4);
  ihdr[8] = 8;  // bit depth
  ihdr[9] = 2;  // RGB
  const raw = Buffer.alloc((m.width * 3 + 1) * m.height);
  for (let y = 0; y < m.height; ++y) {
    raw[y * (m.width * 3 + 1)] = 0;
    Buffer.from(m.data.buffer, m.data.byteOffset + y * m.step, m.width * 3).copy(raw, y * (m.width * 3 + 1) + 1);
  }
  return Buffer.concat([Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]), chunk("IHDR", ihdr),
                        chunk("IDAT", zlib.deflateSync(raw)), chunk("IEND", Buffer.alloc(0))]);
}

async function main() {
  const args = parseArgs(process.argv);
  if (args.png) savePng = (m) => fs.writeFileSync(args.png, pngOf(m));
  const node = new RosNode({
    name: "foxglove_peer",
    domainId: args.domain,
    addresses: ["127.0.0.1"],
    udpSocketCreate: UdpSocketNode.Create,
    log: args.debug ? { debug: (m) => console.error(m), info: (m) => console.error(m), warn: (m) => console.error(m),
                        error: (m) => console.error(m) } : undefined,
  });
  const participant = node._participant;  // the library's own; its subscribe() takes the QoS
  // @foxglove/rtps 1.6 sends a reader's ACKNACK and NACK_FRAG to the remote participant's
  // metatraffic locators also for user (non-builtin) writers. Fast DDS takes them only on the
  // default (user traffic) locators, so a Fast DDS writer never resends what the peer missed: no
  // transient-local sample (/tf_static, /robot_description, the graph) and no lost fragment of an
  // image ever arrives. Cyclone DDS takes them on any port. The peer sends them where RTPS says.
  const userLocators = (guidPrefix, writerEntityId, locators) => {
    const id = typeof writerEntityId === "number" ? writerEntityId : parseInt(String(writerEntityId), 16);
    const remote = participant._participants.get(guidPrefix);
    return (id & 0xc0) === 0 && remote != undefined ? remote.attributes.defaultUnicastLocatorList : locators;
  };
  const sendAckNackTo = participant.sendAckNackTo.bind(participant);
  participant.sendAckNackTo = (reader, guidPrefix, writerEntityId, first, last, final, locators) =>
    sendAckNackTo(reader, guidPrefix, writerEntityId, first, last, final, userLocators(guidPrefix, writerEntityId, locators));
  const sendNackFragTo = participant.sendNackFragTo.bind(participant);
  participant.sendNackFragTo = (guidPrefix, lastFragment, readerEntityId, writerEntityId, seq, tracker, locators) =>
    sendNackFragTo(guidPrefix, lastFragment, readerEntityId, writerEntityId, seq, tracker,
                   userLocators(guidPrefix, writerEntityId, locators));
  const stats = new Map();
  for (const s of args.subs) {
    const type = KINDS[s.kind].type;
    const topicName = s.topic.startsWith("/") ? rosTopicToDds(s.topic) : s.topic;
    const rtpsOpts = {
      topicName,
      typeName: rosTypeToDds(type),
      durability: s.qos === "tl" ? rtps.Durability.TransientLocal : rtps.Durability.Volatile,
      reliability: { kind: s.qos === "be" ? rtps.Reliability.BestEffort : rtps.Reliability.Reliable,
                     maxBlockingTime: { sec: 0x7fffffff, nsec: 0xffffffff } },
      history: { kind: rtps.HistoryKind.KeepLast, depth: s.kind === "tf_static" ? 100 : 10 },
    };
    const readerEntityId = participant.subscribe(rtpsOpts);
    const sub = new Subscription({ subscribeOpts: rtpsOpts, readerEntityId, participant, skipParsing: true });
    const reader = new MessageReader(definitionOf(args.distro, type));
    const st = { count: 0, first: 0, last: 0, lastText: null, errors: 0, children: new Set() };
    stats.set(s.topic, st);
    sub.on("message", (_time, _msg, data) => {
      let text;
      try {
        text = describe(s.kind, reader.readMessage(data));
      } catch (e) {
        st.errors += 1;
        if (st.errors <= 3) console.log(JSON.stringify({ topic: s.topic, error: String(e) }));
        return;
      }
      if (s.kind === "tf" || s.kind === "tf_static") for (const t of text.transforms) st.children.add(t.child);
      const now = performance.now() / 1000;
      if (st.count === 0) st.first = now;
      st.last = now;
      st.count += 1;
      st.lastText = text;
      if (st.count <= 3) console.log(JSON.stringify({ topic: s.topic, n: st.count, sample: text }));
    });
  }
  await node.start();
  await new Promise((resolve) => setTimeout(resolve, args.seconds * 1000));
  for (const s of args.subs) {
    const st = stats.get(s.topic);
    console.log(JSON.stringify({ topic: s.topic, summary: true, count: st.count, span: st.count > 1 ? st.last - st.first : 0,
                                 errors: st.errors, children: [...st.children], last: st.lastText }));
  }
  await node.shutdown();
  process.exit(0);
}

main().catch((e) => {
  console.error(`foxglove peer: ${e.stack ?? e}`);
  process.exit(1);
});
