// Writes one IMU recording as a text file and as ROS bags of every kind accelcal reads, with
// code nobody in this project wrote: MCAP through @mcap/core (chunks compressed by the npm
// compressors MCAP's docs suggest: @foxglove/wasm-zstd, and lz4js for LZ4 frames), ROS 2
// messages through @foxglove/rosmsg2-serialization (CDR), ROS 2 SQLite bags through sql.js (the
// SQLite library compiled to WebAssembly) with the tables rosbag2's sqlite3 storage creates,
// ROS 1 messages through @foxglove/rosmsg-serialization. No npm package writes ROS 1 bags: those
// are laid out here from the published format description (wiki.ros.org/Bags/Format/2.0), and
// read_ros1.mjs reads them back with @foxglove/rosbag to prove them.
//
// Usage: node write_bags.mjs SAMPLES OUTDIR [--variant NAME] [--forms LIST]
//   SAMPLES  lines "t ax ay az" in ADC counts (accelcal's text recording); converted to m/s^2 as
//            an IMU driver would, a = (counts - 2048) / 34.8, and stamped from t
//            (1700000000 s + t, to the nanosecond)
//   OUTDIR   gets imu.txt (the same samples as text: "t ax ay az", t = sec + nanosec * 1e-9
//            and the values as JavaScript prints doubles, exactly) and the bags:
//            imu_zstd.mcap, imu_lz4.mcap, imu_none.mcap, imu.db3, imu_sqlite/ and imu_mcapdir/
//            (ROS 2 bag folders with metadata.yaml), imu_none.bag, imu_bz2.bag, imu_lz4.bag.
//            Each bag also holds /status (a std_msgs String at about 1 Hz): a topic of another type.
//   --variant two_imu       a second IMU topic, /imu/raw (the same samples)
//   --variant swapped       the stamps of messages 1000 and 1001 swapped (t goes back)
//   --variant zero_stamps   every header stamp zero (a driver that never set them)
//   --variant wrong_schema  (MCAP) the IMU channel's schema says sensor_msgs/msg/Imu but defines
//                           its Header with a seq field, as ROS 1's
//   --forms LIST            only these bags (comma-separated: mcap_zstd, mcap_lz4, mcap_none, db3,
//                           folders, bag_none, bag_bz2, bag_lz4; default all)
import fs from "node:fs";
import path from "node:path";
import { McapWriter } from "@mcap/core";
import * as zstd from "@foxglove/wasm-zstd";
import lz4js from "lz4js";
import compressjs from "compressjs";
import initSqlJs from "sql.js";
import { MessageWriter as CdrWriter } from "@foxglove/rosmsg2-serialization";
import { MessageWriter as Ros1Writer } from "@foxglove/rosmsg-serialization";
import common from "@foxglove/rosmsg-msgs-common";
import { stringify, md5 } from "@foxglove/rosmsg";

const [samplesPath, outDir, ...rest] = process.argv.slice(2);
const option = (name, fallback) => (rest.indexOf(name) >= 0 ? rest[rest.indexOf(name) + 1] : fallback);
const variant = option("--variant", "");
const formsOption = option("--forms", "all");
const wanted = (form) => formsOption === "all" || formsOption.split(",").includes(form);
if (!samplesPath || !outDir) {
  console.error("usage: node write_bags.mjs SAMPLES OUTDIR [--variant NAME]");
  process.exit(2);
}
fs.mkdirSync(outDir, { recursive: true });

const EPOCH_NS = 1700000000n * 1000000000n;
const IMU_TOPIC = "/imu/data";

// The definitions of a type and of every type it uses, the type's own first.
function definitionsOf(table, root) {
  const out = [];
  const seen = new Set();
  const visit = (name) => {
    if (seen.has(name)) return;
    seen.add(name);
    const d = table[name];
    if (!d) throw new Error(`no definition of ${name}`);
    out.push(d);
    for (const f of d.definitions) if (f.isComplex) visit(f.type);
  };
  visit(root);
  return out;
}
const ros2Imu = definitionsOf(common.ros2humble, "sensor_msgs/Imu");
const ros2String = definitionsOf(common.ros2humble, "std_msgs/String");
const ros1Imu = definitionsOf(common.ros1, "sensor_msgs/Imu");
const ros1String = definitionsOf(common.ros1, "std_msgs/String");
const cdrImu = new CdrWriter(ros2Imu);
const cdrString = new CdrWriter(ros2String);
const ros1ImuWriter = new Ros1Writer(ros1Imu);
const ros1StringWriter = new Ros1Writer(ros1String);

// --- The samples -----------------------------------------------------------------------------
const samples = [];
for (const line of fs.readFileSync(samplesPath, "utf8").split("\n")) {
  const f = line.trim().split(/[\s,]+/);
  if (f.length < 4 || f[0].startsWith("#") || Number.isNaN(Number(f[0]))) continue;
  const tNs = EPOCH_NS + BigInt(Math.round(Number(f[0]) * 1e9));
  const a = f.slice(1, 4).map((c) => (Number(c) - 2048) / 34.8);
  samples.push({ sec: Number(tNs / 1000000000n), nsec: Number(tNs % 1000000000n), a });
}
if (variant === "swapped") {
  const i = 1000;
  [samples[i].sec, samples[i + 1].sec] = [samples[i + 1].sec, samples[i].sec];
  [samples[i].nsec, samples[i + 1].nsec] = [samples[i + 1].nsec, samples[i].nsec];
}
// The bag's receive time: the stamp and a transport delay of 1.0 to 1.4 ms, in order.
let lastReceive = 0n;
for (const [i, s] of samples.entries()) {
  const stamp = BigInt(s.sec) * 1000000000n + BigInt(s.nsec);
  let r = stamp + 1000000n + BigInt((i * 7919) % 400000);
  if (r <= lastReceive) r = lastReceive + 1000n;
  s.receiveNs = r;
  lastReceive = r;
}
if (variant === "zero_stamps") for (const s of samples) s.sec = s.nsec = 0;

// The text: t as the bag reader computes it from the stamp, the values as doubles print.
{
  const fd = fs.openSync(path.join(outDir, "imu.txt"), "w");
  for (let i = 0; i < samples.length; i += 10000) {
    const text = samples.slice(i, i + 10000).map((s) => `${s.sec + s.nsec * 1e-9} ${s.a[0]} ${s.a[1]} ${s.a[2]}\n`);
    fs.writeSync(fd, text.join(""));
  }
  fs.closeSync(fd);
}

// /status, a String topic at about 1 Hz over the same span.
const statuses = [];
for (let i = 0; i < samples.length; i += 100) statuses.push({ receiveNs: samples[i].receiveNs + 1n, text: `ok ${i}` });

// Every message of a bag in receive order: [topic, receiveNs, sample or status].
function timeline(imuTopics) {
  const out = [];
  let j = 0;
  for (const s of samples) {
    while (j < statuses.length && statuses[j].receiveNs <= s.receiveNs) out.push(["/status", statuses[j].receiveNs, statuses[j++]]);
    for (const topic of imuTopics) out.push([topic, s.receiveNs, s]);
  }
  while (j < statuses.length) out.push(["/status", statuses[j].receiveNs, statuses[j++]]);
  return out;
}
const imuTopics = variant === "two_imu" ? [IMU_TOPIC, "/imu/raw"] : [IMU_TOPIC];
const messages = timeline(imuTopics);

const zeros9 = new Array(9).fill(0);
function imuObject(s, ros1) {
  const header = ros1 ? { seq: 0, stamp: { sec: s.sec, nsec: s.nsec }, frame_id: "imu_link" }
                      : { stamp: { sec: s.sec, nanosec: s.nsec }, frame_id: "imu_link" };
  return {
    header,
    orientation: { x: 0, y: 0, z: 0, w: 1 },
    orientation_covariance: [-1, 0, 0, 0, 0, 0, 0, 0, 0],
    angular_velocity: { x: 0.001, y: -0.002, z: 0.0005 },
    angular_velocity_covariance: zeros9,
    linear_acceleration: { x: s.a[0], y: s.a[1], z: s.a[2] },
    linear_acceleration_covariance: zeros9,
  };
}

// --- MCAP (ROS 2 profile) ---------------------------------------------------------------------
// The writer's output, straight to the file.
class Sink {
  constructor(file) { this.fd = fs.openSync(file, "w"); this.size = 0n; }
  async write(buffer) { fs.writeSync(this.fd, buffer); this.size += BigInt(buffer.byteLength); }
  position() { return this.size; }
  close() { fs.closeSync(this.fd); }
}

async function writeMcap(file, compression) {
  await zstd.isLoaded;
  const compressors = {
    zstd: (data) => ({ compression: "zstd", compressedData: zstd.compress(data, 3) }),
    lz4: (data) => ({ compression: "lz4", compressedData: lz4js.compress(data) }),
    none: undefined,
  };
  const sink = new Sink(file);
  const writer = new McapWriter({ writable: sink, chunkSize: 64 * 1024, compressChunk: compressors[compression] });
  await writer.start({ profile: "ros2", library: "write_bags.mjs (@mcap/core)" });
  let imuDefinition = stringify(ros2Imu);
  if (variant === "wrong_schema") imuDefinition = stringify(ros1Imu);  // ROS 1's Header, with seq
  const imuSchema = await writer.registerSchema({ name: "sensor_msgs/msg/Imu", encoding: "ros2msg", data: new TextEncoder().encode(imuDefinition) });
  const stringSchema = await writer.registerSchema({ name: "std_msgs/msg/String", encoding: "ros2msg", data: new TextEncoder().encode(stringify(ros2String)) });
  const channels = {};
  for (const topic of [...imuTopics, "/status"]) {
    channels[topic] = await writer.registerChannel({
      topic, messageEncoding: "cdr", schemaId: topic === "/status" ? stringSchema : imuSchema,
      metadata: new Map([["offered_qos_profiles", ""]]),
    });
  }
  let sequence = 0;
  for (const [topic, receiveNs, m] of messages) {
    const data = topic === "/status" ? cdrString.writeMessage({ data: m.text }) : cdrImu.writeMessage(imuObject(m, false));
    await writer.addMessage({ channelId: channels[topic], sequence: sequence++, logTime: receiveNs, publishTime: receiveNs, data });
  }
  await writer.end();
  sink.close();
}

// --- ROS 2 SQLite (rosbag2's sqlite3 storage, schema version 3 as Humble writes it) -----------
async function writeDb3(file) {
  const SQL = await initSqlJs();
  const db = new SQL.Database();
  db.run("CREATE TABLE schema(schema_version INTEGER PRIMARY KEY, ros_distro TEXT NOT NULL);");
  db.run("CREATE TABLE metadata(id INTEGER PRIMARY KEY, metadata_version INTEGER NOT NULL, metadata TEXT NOT NULL);");
  db.run("CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL, serialization_format TEXT NOT NULL, offered_qos_profiles TEXT NOT NULL);");
  db.run("CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL, timestamp INTEGER NOT NULL, data BLOB NOT NULL);");
  db.run("CREATE INDEX timestamp_idx ON messages (timestamp ASC);");
  db.run("INSERT INTO schema (schema_version, ros_distro) VALUES (3, 'humble');");
  const ids = {};
  for (const topic of [...imuTopics, "/status"]) {
    db.run("INSERT INTO topics (name, type, serialization_format, offered_qos_profiles) VALUES (?, ?, 'cdr', '')",
      [topic, topic === "/status" ? "std_msgs/msg/String" : "sensor_msgs/msg/Imu"]);
    ids[topic] = db.exec("SELECT last_insert_rowid()")[0].values[0][0];
  }
  db.run("BEGIN");
  const insert = db.prepare("INSERT INTO messages (timestamp, topic_id, data) VALUES (?, ?, ?)");
  for (const [topic, receiveNs, m] of messages) {
    const data = topic === "/status" ? cdrString.writeMessage({ data: m.text }) : cdrImu.writeMessage(imuObject(m, false));
    // sql.js binds numbers as doubles: receive times in ns (1.7e18) need BigInt to stay exact.
    insert.run([receiveNs, ids[topic], data]);
  }
  insert.free();
  db.run("COMMIT");
  fs.writeFileSync(file, Buffer.from(db.export()));
  db.close();
}

// rosbag2's metadata.yaml (version 5), as `ros2 bag record` leaves it beside its files.
function writeMetadata(folder, storage, fileName) {
  const counts = new Map();
  for (const [topic] of messages) counts.set(topic, (counts.get(topic) ?? 0) + 1);
  const first = messages[0][1];
  const last = messages[messages.length - 1][1];
  const topics = [...counts].map(([topic, n]) => `    - topic_metadata:
        name: ${topic}
        type: ${topic === "/status" ? "std_msgs/msg/String" : "sensor_msgs/msg/Imu"}
        serialization_format: cdr
        offered_qos_profiles: ""
      message_count: ${n}`).join("\n");
  fs.writeFileSync(path.join(folder, "metadata.yaml"), `rosbag2_bagfile_information:
  version: 5
  storage_identifier: ${storage}
  duration:
    nanoseconds: ${last - first}
  starting_time:
    nanoseconds_since_epoch: ${first}
  message_count: ${messages.length}
  topics_with_message_count:
${topics}
  compression_format: ""
  compression_mode: ""
  relative_file_paths:
    - ${fileName}
  files:
    - path: ${fileName}
      starting_time:
        nanoseconds_since_epoch: ${first}
      duration:
        nanoseconds: ${last - first}
      message_count: ${messages.length}
`);
}

// --- ROS 1 bag, format 2.0, laid out from the published description --------------------------
function u32(v) { const b = Buffer.alloc(4); b.writeUInt32LE(v); return b; }
function u64(v) { const b = Buffer.alloc(8); b.writeBigUInt64LE(BigInt(v)); return b; }
function rosTime(ns) { return Buffer.concat([u32(Number(ns / 1000000000n)), u32(Number(ns % 1000000000n))]); }
// A record header: <len>name=value fields.
function fields(pairs) {
  return Buffer.concat(pairs.map(([name, value]) => {
    const field = Buffer.concat([Buffer.from(name + "="), Buffer.isBuffer(value) ? value : Buffer.from(value)]);
    return Buffer.concat([u32(field.length), field]);
  }));
}
function record(headerPairs, data) {
  const header = fields(headerPairs);
  return Buffer.concat([u32(header.length), header, u32(data.length), data]);
}
const op = (code) => ["op", Buffer.from([code])];

function writeRos1(file, compression) {
  const conns = [...imuTopics, "/status"].map((topic, id) => ({
    id, topic,
    definitions: topic === "/status" ? ros1String : ros1Imu,
    type: topic === "/status" ? "std_msgs/String" : "sensor_msgs/Imu",
  }));
  const connOf = Object.fromEntries(conns.map((c) => [c.topic, c]));
  const connectionRecord = (c) => record([op(0x07), ["conn", u32(c.id)], ["topic", c.topic]],
    fields([["topic", c.topic], ["type", c.type], ["md5sum", md5(c.definitions)],
            ["message_definition", stringify(c.definitions)], ["callerid", "/imu_driver"], ["latching", "0"]]));
  const fd = fs.openSync(file, "w");
  const parts = { push: (b) => fs.writeSync(fd, b) };
  parts.push(Buffer.from("#ROSBAG V2.0\n"));
  const headerAt = 13;
  parts.push(Buffer.alloc(4096));  // the bag header, written last (it holds index_pos)
  let pos = headerAt + 4096;
  const chunkInfos = [];
  const written = new Set();
  const perChunk = 2000;  // messages per chunk
  for (let start = 0; start < messages.length; start += perChunk) {
    const slice = messages.slice(start, start + perChunk);
    const inner = [];
    let innerSize = 0;
    const index = new Map();  // conn -> [[time, offset]]
    for (const [topic, receiveNs, m] of slice) {
      const c = connOf[topic];
      if (!written.has(c.id)) {
        written.add(c.id);
        const r = connectionRecord(c);
        inner.push(r);
        innerSize += r.length;
      }
      const data = topic === "/status" ? ros1StringWriter.writeMessage({ data: m.text }) : ros1ImuWriter.writeMessage(imuObject(m, true));
      const r = record([op(0x02), ["conn", u32(c.id)], ["time", rosTime(receiveNs)]], Buffer.from(data));
      if (!index.has(c.id)) index.set(c.id, []);
      index.get(c.id).push([receiveNs, innerSize]);
      inner.push(r);
      innerSize += r.length;
    }
    const raw = Buffer.concat(inner);
    const packed = compression === "bz2" ? Buffer.from(compressjs.Bzip2.compressFile(raw))
                 : compression === "lz4" ? Buffer.from(lz4js.compress(raw))
                 : raw;
    const chunk = record([op(0x05), ["compression", compression], ["size", u32(raw.length)]], packed);
    const chunkPos = pos;
    parts.push(chunk);
    pos += chunk.length;
    for (const [conn, entries] of index) {
      const data = Buffer.concat(entries.map(([t, offset]) => Buffer.concat([rosTime(t), u32(offset)])));
      const r = record([op(0x04), ["ver", u32(1)], ["conn", u32(conn)], ["count", u32(entries.length)]], data);
      parts.push(r);
      pos += r.length;
    }
    chunkInfos.push({ chunkPos, start: slice[0][1], end: slice[slice.length - 1][1],
                      counts: [...index].map(([conn, e]) => [conn, e.length]) });
  }
  const indexPos = pos;
  for (const c of conns) parts.push(connectionRecord(c));
  for (const ci of chunkInfos) {
    const data = Buffer.concat(ci.counts.map(([conn, n]) => Buffer.concat([u32(conn), u32(n)])));
    parts.push(record([op(0x06), ["ver", u32(1)], ["chunk_pos", u64(ci.chunkPos)], ["start_time", rosTime(ci.start)],
                       ["end_time", rosTime(ci.end)], ["count", u32(ci.counts.length)]], data));
  }
  // The bag header record, padded with spaces to 4096 bytes in all.
  const header = fields([op(0x03), ["index_pos", u64(indexPos)], ["conn_count", u32(conns.length)], ["chunk_count", u32(chunkInfos.length)]]);
  const padding = 4096 - 4 - header.length - 4;
  fs.writeSync(fd, Buffer.concat([u32(header.length), header, u32(padding), Buffer.alloc(padding, " ")]), 0, 4096, headerAt);
  fs.closeSync(fd);
}

// --- All of them ------------------------------------------------------------------------------
const out = (name) => path.join(outDir, name);
if (wanted("mcap_zstd") || wanted("folders")) await writeMcap(out("imu_zstd.mcap"), "zstd");
if (variant !== "wrong_schema") {
  if (wanted("mcap_lz4")) await writeMcap(out("imu_lz4.mcap"), "lz4");
  if (wanted("mcap_none")) await writeMcap(out("imu_none.mcap"), "none");
  if (wanted("db3") || wanted("folders")) await writeDb3(out("imu.db3"));
  if (wanted("folders")) {
    fs.mkdirSync(out("imu_sqlite"), { recursive: true });
    fs.copyFileSync(out("imu.db3"), out("imu_sqlite/imu_sqlite_0.db3"));
    writeMetadata(out("imu_sqlite"), "sqlite3", "imu_sqlite_0.db3");
    fs.mkdirSync(out("imu_mcapdir"), { recursive: true });
    fs.copyFileSync(out("imu_zstd.mcap"), out("imu_mcapdir/imu_mcapdir_0.mcap"));
    writeMetadata(out("imu_mcapdir"), "mcap", "imu_mcapdir_0.mcap");
  }
  for (const c of ["none", "bz2", "lz4"]) if (wanted(`bag_${c}`)) writeRos1(out(`imu_${c}.bag`), c);
}
console.log(`wrote ${samples.length} IMU samples on ${imuTopics.join(", ")} and ${statuses.length} /status messages to ${outDir}`);
