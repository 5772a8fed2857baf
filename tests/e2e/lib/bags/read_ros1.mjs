// Reads a ROS 1 bag with readers nobody in this project wrote, to prove the bags write_bags.mjs
// lays out by hand: @foxglove/rosbag (the bag: header, chunks, index, connections), its chunks
// decompressed by @foxglove/wasm-bz2 and @foxglove/wasm-lz4, each message decoded by
// @foxglove/rosmsg-serialization from the message_definition the bag itself carries, whose
// md5sum @foxglove/rosmsg recomputes.
//
// Usage: node read_ros1.mjs BAG TOPIC
// Prints each message on TOPIC as "t ax ay az" (t = header.stamp.sec + nsec * 1e-9, the values
// of linear_acceleration as JavaScript prints doubles: the lines of write_bags.mjs's imu.txt),
// and on stderr the topics with their types and message counts. Exit status 1 on any mismatch
// between a connection's md5sum and its definition.
import fs from "node:fs";
import { Bag } from "@foxglove/rosbag";
import Bzip2 from "@foxglove/wasm-bz2";
import lz4 from "@foxglove/wasm-lz4";
import { MessageReader } from "@foxglove/rosmsg-serialization";
import { parse, md5 } from "@foxglove/rosmsg";

const [bagPath, topic] = process.argv.slice(2);
const bytes = fs.readFileSync(bagPath);
const bzip2 = await Bzip2.init();
await lz4.isLoaded;
const bag = new Bag({
  read: async (offset, length) => bytes.subarray(offset, offset + length),
  size: () => bytes.length,
}, {
  parse: false,
  decompress: {
    bz2: (buffer, size) => bzip2.decompress(buffer, size, { small: false }),
    lz4: (buffer, size) => lz4(buffer, size),
  },
});
await bag.open();

const readers = new Map();
const counts = new Map();
for (const [id, c] of bag.connections) {
  const definitions = parse(c.messageDefinition, { ros2: false });
  const computed = md5(definitions);
  if (computed !== c.md5sum) {
    console.error(`connection ${id} (${c.topic}): md5sum ${c.md5sum}, its definition gives ${computed}`);
    process.exit(1);
  }
  readers.set(id, new MessageReader(definitions));
  counts.set(c.topic, { type: c.type, n: 0 });
}
const lines = [];
for await (const event of bag.messageIterator()) {
  const connection = bag.connections.get(event.connectionId);
  counts.get(connection.topic).n += 1;
  if (connection.topic !== topic) continue;
  const m = readers.get(event.connectionId).readMessage(event.data);
  const a = m.linear_acceleration;
  lines.push(`${m.header.stamp.sec + m.header.stamp.nsec * 1e-9} ${a.x} ${a.y} ${a.z}`);
}
for (const [name, { type, n }] of counts) console.error(`${name} ${type} ${n}`);
process.stdout.write(lines.join("\n") + (lines.length ? "\n" : ""));
