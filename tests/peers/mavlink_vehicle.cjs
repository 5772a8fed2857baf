// A test vehicle built on node-mavlink (someone else's MAVLink implementation, generated from the
// same XML as ours): it turns the virtual bench's sample lines (`accelcal record --source sim -o -`
// on stdin, `t ax ay az [temp_c]` in counts) into what a flight controller sends, and answers
// what a ground station asks. Every frame accelcal reads is encoded here by node-mavlink, and
// every frame accelcal sends is checked here by node-mavlink's splitter (CRC with its own
// CRC_EXTRA table): the summary (--summary FILE, written on exit) counts both.
//
// The vehicle, as ArduPilot or PX4 does it: the driver scales the counts, a = (raw - B) / S
// (--bias, --scale: the sensor's datasheet figures); its own stored calibration corrects them,
// (a - OFFS) * SCAL per axis; the board orientation rotates them to the body frame; then
// HIGHRES_IMU (float m/s^2), SCALED_IMU/2/3 (mG) or RAW_IMU (the raw counts) go out at the rate
// asked by SET_MESSAGE_INTERVAL (or REQUEST_DATA_STREAM with --old-firmware). Parameters are a
// table (--param NAME=VALUE[:TYPE]) answered by PARAM_REQUEST_READ/LIST and changed by
// PARAM_SET, which is echoed; a changed calibration applies to the next samples, as on a vehicle.
//
// Several IMUs, each with its own truth (issue 31): --bench-truth B;K;M names the bench's sensor
// (its bias counts, scale counts/(m/s^2) and misalignment a_yz,a_zy,a_zx rad: the scenario's
// [sensor]), and each --imu-truth B;K;M one IMU instance (0, 1, 2 in order). Every sample line
// is taken back to the specific force on the bench's platform, a_p = T0 (raw - B0) / K0, then
// each IMU reads raw_i = K_i T_i^-1 a_p + B_i (the model of docs/model.md, written out here on
// its own), its counts sent as they are in RAW_IMU, or as raw_i / 1000 m/s^2 corrected by that
// IMU's stored calibration (INS_ACC2OFFS_X ..., --param) in HIGHRES_IMU and SCALED_IMU2/3: the
// truth is the sensor's own, which the vehicle's correction hides. --msg ardupilot sends what
// ArduPilot sends for three IMUs: RAW_IMU (id 0), SCALED_IMU2 and SCALED_IMU3. --silent-imu I:
// instance I never sends.
//
// Faults (each one of the clumsy bench's): --reboot-at S or SIGUSR1 (the vehicle goes away for
// 2.5 s and comes back with its clock and sequence at 0), --drop P (that share of IMU frames never sent:
// sequence gaps), --sign (MAVLink 2 signing on), --bad-crc-every N, --garbage-every N (100 random
// bytes), --unknown-every N (a frame of a message no dialect has), --wrong-length-every N (a
// HIGHRES_IMU 7 bytes too long, CRC right), --no-params, --wrong-echo NAME, --no-echo NAME,
// --silent-after S (stops sending, the link held open), --v1 (MAVLink 1 framing).
//
// Usage: node mavlink_vehicle.cjs --tcp 0 [options] < samples.txt   (prints "port N" first)
'use strict';
const path = require('path');
const net = require('net');
const dgram = require('dgram');
const fs = require('fs');
const readline = require('readline');

const modules = process.env.ACCELCAL_NODE_MODULES;
if (!modules) { console.error('vehicle: ACCELCAL_NODE_MODULES is not set'); process.exit(2); }
const mav = require(path.join(modules, 'node-mavlink'));
const { MavLinkProtocolV1, MavLinkProtocolV2, MavLinkPacketSplitter, MavLinkPacketParser,
        MavLinkPacketSignature, common, minimal, x25crc, MSG_ID_MAGIC_NUMBER } = mav;

// ---- options ----
const opt = {
  tcp: null, udpListen: null, udpTo: null, msg: 'highres', imu: 0, secondImu: false,
  autopilot: 'ardupilot', scale: 34.8, bias: 2048, params: [], defaultRate: 4,
  oldFirmware: false, rebootAt: null, drop: 0, sign: false, badCrcEvery: 0, garbageEvery: 0,
  unknownEvery: 0, wrongLengthEvery: 0, noParams: false, wrongEcho: null, noEcho: null,
  silentAfter: null, v1: false, seed: 1, summary: null, system: 1, component: 1,
  benchTruth: null, imuTruths: [], silentImu: null,
};
// "bx,by,bz;kx,ky,kz;yz,zy,zx" -> { b, k, m: [yz, zy, zx] }
function parseTruth(text) {
  const [b, k, m] = text.split(';').map(part => part.split(',').map(Number));
  if (![b, k, m].every(v => v && v.length === 3 && v.every(Number.isFinite))) {
    console.error(`vehicle: a truth is "bx,by,bz;kx,ky,kz;yz,zy,zx", not ${text}`); process.exit(2);
  }
  return { b, k, m };
}
const argv = process.argv.slice(2);
for (let i = 0; i < argv.length; ++i) {
  const a = argv[i], next = () => argv[++i];
  switch (a) {
    case '--tcp': opt.tcp = Number(next()); break;
    case '--udp-listen': opt.udpListen = Number(next()); break;
    case '--udp-to': opt.udpTo = Number(next()); break;
    case '--msg': opt.msg = next(); break;
    case '--imu': opt.imu = Number(next()); break;
    case '--second-imu': opt.secondImu = true; break;
    case '--autopilot': opt.autopilot = next(); break;
    case '--scale': opt.scale = Number(next()); break;
    case '--bias': opt.bias = Number(next()); break;
    case '--param': opt.params.push(next()); break;
    case '--default-rate': opt.defaultRate = Number(next()); break;
    case '--old-firmware': opt.oldFirmware = true; break;
    case '--reboot-at': opt.rebootAt = Number(next()); break;
    case '--drop': opt.drop = Number(next()); break;
    case '--sign': opt.sign = true; break;
    case '--bad-crc-every': opt.badCrcEvery = Number(next()); break;
    case '--garbage-every': opt.garbageEvery = Number(next()); break;
    case '--unknown-every': opt.unknownEvery = Number(next()); break;
    case '--wrong-length-every': opt.wrongLengthEvery = Number(next()); break;
    case '--no-params': opt.noParams = true; break;
    case '--wrong-echo': opt.wrongEcho = next(); break;
    case '--no-echo': opt.noEcho = next(); break;
    case '--silent-after': opt.silentAfter = Number(next()); break;
    case '--v1': opt.v1 = true; break;
    case '--seed': opt.seed = Number(next()); break;
    case '--summary': opt.summary = next(); break;
    case '--bench-truth': opt.benchTruth = parseTruth(next()); break;
    case '--imu-truth': opt.imuTruths.push(parseTruth(next())); break;
    case '--silent-imu': opt.silentImu = Number(next()); break;
    default: console.error(`vehicle: unknown option ${a}`); process.exit(2);
  }
}

// A small deterministic generator (faults repeat run to run).
let rngState = opt.seed >>> 0 || 1;
function random() {
  rngState ^= rngState << 13; rngState >>>= 0;
  rngState ^= rngState >>> 17;
  rngState ^= rngState << 5; rngState >>>= 0;
  return rngState / 4294967296;
}

// ---- parameters ----
const REAL32 = 9, INT32 = 6, INT8 = 2;
const ardupilot = opt.autopilot === 'ardupilot';
const params = new Map();
function defineParam(name, value, type = REAL32) { params.set(name, { value: Math.fround(value), type }); }
if (ardupilot) {
  for (const prefix of ['INS_ACC', 'INS_ACC2', 'INS_ACC3']) {
    for (const ax of ['X', 'Y', 'Z']) { defineParam(`${prefix}OFFS_${ax}`, 0); defineParam(`${prefix}SCAL_${ax}`, 1); }
  }
  defineParam('INS_ACC_ID', 2753028, INT32); defineParam('INS_ACC2_ID', 2753036, INT32);
  defineParam('INS_ACC3_ID', 0, INT32);
  defineParam('AHRS_ORIENTATION', 0, INT8);
  defineParam('INS_TCAL1_ENABLE', 0, INT8); defineParam('INS_TCAL2_ENABLE', 0, INT8);
  defineParam('INS_TCAL3_ENABLE', 0, INT8);
} else {
  for (const n of [0, 1, 2]) {
    defineParam(`CAL_ACC${n}_ID`, n === 2 ? 0 : 1310988 + 8 * n, INT32);
    for (const ax of ['X', 'Y', 'Z']) { defineParam(`CAL_ACC${n}_${ax}OFF`, 0); defineParam(`CAL_ACC${n}_${ax}SCALE`, 1); }
    defineParam(`CAL_ACC${n}_ROT`, -1, INT32);
  }
  defineParam('SENS_BOARD_ROT', 0, INT32);
  for (const ax of ['X', 'Y', 'Z']) defineParam(`SENS_BOARD_${ax}_OFF`, 0);
  defineParam('TC_A_ENABLE', 0, INT32);
}
for (const p of opt.params) {
  const [name, rest] = p.split('=');
  const [value, type] = rest.split(':');
  defineParam(name, Number(value), type ? Number(type) : (params.get(name) || { type: REAL32 }).type);
}
const paramNames = [...params.keys()];

// PX4 encodes integer parameters bytewise in the float; ArduPilot casts them.
function wireFloat(p) {
  if (p.type === REAL32 || ardupilot) return p.value;
  const b = Buffer.alloc(4); b.writeInt32LE(Math.round(p.value)); return b.readFloatLE(0);
}
function fromWire(value, type) {
  if (type === REAL32 || ardupilot) return Math.fround(value);
  const b = Buffer.alloc(4); b.writeFloatLE(value); return b.readInt32LE(0);
}

// ---- the vehicle's own correction ----
function deg(x) { return x * Math.PI / 180; }
// v_body = Rz(yaw) Ry(pitch) Rx(roll) v_sensor, written out here on its own (independent of
// accelcal's table): the few orientations the tests use.
const ORIENTATIONS = { 0: [0, 0, 0], 2: [0, 0, 90], 4: [0, 0, 180], 8: [180, 0, 0], 10: [180, 0, 90], 24: [0, 90, 0] };
function rotate(v, rpy) {
  const [r, p, y] = rpy.map(deg);
  let [x0, y0, z0] = v;
  let x1 = x0, y1 = Math.cos(r) * y0 - Math.sin(r) * z0, z1 = Math.sin(r) * y0 + Math.cos(r) * z0;
  let x2 = Math.cos(p) * x1 + Math.sin(p) * z1, y2 = y1, z2 = -Math.sin(p) * x1 + Math.cos(p) * z1;
  return [Math.cos(y) * x2 - Math.sin(y) * y2, Math.sin(y) * x2 + Math.cos(y) * y2, z2];
}
function corrected(counts, instance) {
  return storedCorrection(counts.map(c => (c - opt.bias) / opt.scale), instance);
}
// The IMU instance's stored calibration and the board's orientation applied to what its driver
// read (m/s^2): a_sent = R_board ((a_sensor - offset) .* scale).
function storedCorrection(driver, instance) {
  const get = name => params.get(name).value;
  let off, scl, rot;
  if (ardupilot) {
    const prefix = ['INS_ACC', 'INS_ACC2', 'INS_ACC3'][instance];
    off = ['X', 'Y', 'Z'].map(a => get(`${prefix}OFFS_${a}`));
    scl = ['X', 'Y', 'Z'].map(a => get(`${prefix}SCAL_${a}`));
    rot = ORIENTATIONS[get('AHRS_ORIENTATION')];
  } else {
    off = ['X', 'Y', 'Z'].map(a => get(`CAL_ACC${instance}_${a}OFF`));
    scl = ['X', 'Y', 'Z'].map(a => get(`CAL_ACC${instance}_${a}SCALE`));
    rot = ORIENTATIONS[get('SENS_BOARD_ROT')];
  }
  if (!rot) { console.error('vehicle: orientation not in the test table'); process.exit(2); }
  return rotate(driver.map((a, j) => (a - off[j]) * scl[j]), rot);
}

// The bench's counts back to the platform's specific force: a_a = (raw - B) / K, a_p = T a_a
// with T = [[1, -a_yz, a_zy], [0, 1, -a_zx], [0, 0, 1]].
function platformForce(raw, truth) {
  const [yz, zy, zx] = truth.m;
  const [x, y, z] = raw.map((c, j) => (c - truth.b[j]) / truth.k[j]);
  return [x - yz * y + zy * z, y - zx * z, z];
}
// One IMU's counts for the platform's specific force: a_a = T^-1 a_p (back substitution of the
// unit upper triangle), raw = K a_a + B.
function imuCounts(p, truth) {
  const [yz, zy, zx] = truth.m;
  const z = p[2], y = p[1] + zx * z, x = p[0] + yz * y - zy * z;
  return [x, y, z].map((a, j) => truth.k[j] * a + truth.b[j]);
}

// ---- framing and faults ----
const protocol = opt.v1 ? new MavLinkProtocolV1(opt.system, opt.component)
                        : new MavLinkProtocolV2(opt.system, opt.component, opt.sign ? MavLinkProtocolV2.IFLAG_SIGNED : 0);
const key = MavLinkPacketSignature.key('accelcal test vehicle');
let seq = 0, framesSent = 0, imuFramesSent = 0;
const counts = { dropped: 0, badCrc: 0, garbage: 0, unknown: 0, wrongLength: 0, sent: 0 };

function frameOf(msg) {
  let b = protocol.serialize(msg, seq);
  if (opt.sign && !opt.v1) b = protocol.sign(b, 1, key);
  seq = (seq + 1) & 255;
  return b;
}
// A v2 frame built by hand (for the faults node-mavlink will not make): header, payload, CRC
// with the given CRC_EXTRA.
function rawFrame(msgid, payload, crcExtra) {
  const header = Buffer.from([0xFD, payload.length, 0, 0, seq, opt.system, opt.component,
                              msgid & 0xFF, (msgid >> 8) & 0xFF, (msgid >> 16) & 0xFF]);
  seq = (seq + 1) & 255;
  const b = Buffer.concat([header, payload, Buffer.alloc(2)]);
  b.writeUInt16LE(x25crc(b, 1, 2, crcExtra), b.length - 2);
  return b;
}

let silent = false, rebooting = false;
const outputs = new Set();  // functions that write a buffer to one peer
function write(buffer) {
  if (silent || rebooting) return;
  for (const out of outputs) out(buffer);
}
function send(msg, isImu = false) {
  if (silent || rebooting) return;
  ++framesSent;
  if (isImu) {
    ++imuFramesSent;
    if (opt.drop > 0 && random() < opt.drop) { ++counts.dropped; seq = (seq + 1) & 255; return; }
  }
  let b = frameOf(msg);
  if (isImu && opt.badCrcEvery > 0 && imuFramesSent % opt.badCrcEvery === 0) {
    b = Buffer.from(b); b[12] ^= 0x5A; ++counts.badCrc;
  }
  if (opt.garbageEvery > 0 && framesSent % opt.garbageEvery === 0) {
    const g = Buffer.alloc(100); for (let i = 0; i < g.length; ++i) g[i] = Math.floor(random() * 256);
    write(g); ++counts.garbage;
  }
  if (opt.unknownEvery > 0 && framesSent % opt.unknownEvery === 0) {
    write(rawFrame(0xABCDE, Buffer.from([1, 2, 3, 4, 5, 6, 7, 8]), 77)); ++counts.unknown;
  }
  if (isImu && opt.wrongLengthEvery > 0 && imuFramesSent % opt.wrongLengthEvery === 0) {
    const payload = Buffer.alloc(70, 0x55);
    write(rawFrame(105, payload, MSG_ID_MAGIC_NUMBER[105])); ++counts.wrongLength;
  }
  write(b);
  ++counts.sent;
}

// ---- streams ----
const rates = new Map();  // message id -> Hz asked
const HIGHRES = 105, SCALED = [26, 116, 129], RAW = 27;
if (opt.msg === 'scaled') SCALED.forEach(id => rates.set(id, opt.defaultRate));
if (opt.msg === 'raw') rates.set(RAW, opt.defaultRate);
if (opt.msg === 'ardupilot') [RAW, SCALED[1], SCALED[2]].forEach(id => rates.set(id, opt.defaultRate));
const several = opt.imuTruths.length > 0;
if (several && !opt.benchTruth) { console.error('vehicle: --imu-truth needs --bench-truth'); process.exit(2); }
const nextDue = new Map();  // message id -> t of its next frame
let bootT = null;
const startWall = Date.now();

// Paces one stream (`key`) by the rate asked for message `id`, on the samples' clock.
function due(key, id, t) {
  const hz = rates.get(id);
  if (!hz) return false;
  const at = nextDue.get(key);
  if (at !== undefined && t < at - 1e-9) return false;
  const period = 1 / hz;
  nextDue.set(key, at === undefined || t > at + period ? t + period : at + period);
  return true;
}

function sendHighres(instance, vt, a, temp) {
  const m = new common.HighresImu();
  m.timeUsec = BigInt(Math.round(vt * 1e6));
  [m.xacc, m.yacc, m.zacc] = a;
  m.xgyro = m.ygyro = m.zgyro = m.xmag = m.ymag = m.zmag = 0;
  m.absPressure = m.diffPressure = m.pressureAlt = 0;
  m.temperature = Number.isFinite(temp) ? temp : 0;
  m.fieldsUpdated = 0x7 | (Number.isFinite(temp) ? 4096 : 0);
  m.id = instance;
  send(m, true);
}
function sendScaled(instance, vt, a, temp) {
  const m = instance === 0 ? new common.ScaledImu() : instance === 1 ? new common.ScaledImu2() : new common.ScaledImu3();
  m.timeBootMs = Math.round(vt * 1000);
  [m.xacc, m.yacc, m.zacc] = a.map(v => Math.max(-32768, Math.min(32767, Math.round(v / 9.80665 * 1000))));
  m.xgyro = m.ygyro = m.zgyro = m.xmag = m.ymag = m.zmag = 0;
  m.temperature = Number.isFinite(temp) ? Math.round(temp * 100) || 1 : 0;
  send(m, true);
}
function sendRaw(instance, vt, counts, temp) {
  const m = new common.RawImu();
  m.timeUsec = BigInt(Math.round(vt * 1e6));
  [m.xacc, m.yacc, m.zacc] = counts.map(c => Math.max(-32768, Math.min(32767, Math.round(c))));
  m.xgyro = m.ygyro = m.zgyro = m.xmag = m.ymag = m.zmag = 0;
  m.id = instance;
  m.temperature = Number.isFinite(temp) ? Math.round(temp * 100) || 1 : 0;
  send(m, true);
}

// Several IMUs, each its own truth (--imu-truth), its counts sent as the mode says.
function streamImus(t, vt, raw, temp) {
  const p = platformForce(raw, opt.benchTruth);
  opt.imuTruths.forEach((truth, instance) => {
    if (instance === opt.silentImu) return;
    const counts = imuCounts(p, truth);
    // The driver's m/s^2 (the counts as 0.001 m/s^2) with the IMU's stored calibration, for
    // HIGHRES_IMU and SCALED_IMU*; RAW_IMU's counts go as they are.
    const a = storedCorrection(counts.map(c => c / 1000), instance);
    if (opt.msg === 'highres' && due(HIGHRES * 10 + instance, HIGHRES, t)) sendHighres(instance, vt, a, temp);
    if (opt.msg === 'scaled' && due(SCALED[instance], SCALED[instance], t)) sendScaled(instance, vt, a, temp);
    if (opt.msg === 'raw' && due(RAW * 10 + instance, RAW, t)) sendRaw(instance, vt, counts, temp);
    if (opt.msg === 'ardupilot') {
      if (instance === 0 && due(RAW * 10, RAW, t)) sendRaw(0, vt, counts, temp);
      if (instance > 0 && due(SCALED[instance], SCALED[instance], t)) sendScaled(instance, vt, a, temp);
    }
  });
}

function streamSample(t, raw, temp) {
  if (bootT === null) bootT = t;
  const vt = t - bootT + 0.5;  // the vehicle's clock: s since boot
  if (several) { streamImus(t, vt, raw, temp); return; }
  const instances = opt.secondImu ? [opt.imu, (opt.imu + 1) % 3] : [opt.imu];
  for (const instance of instances) {
    // A second IMU reads twice the first: picking the wrong one cannot go unseen.
    const counts2 = instance === opt.imu ? raw : raw.map(c => 2 * c);
    const a = corrected(counts2, instance);
    if (opt.msg === 'highres' && due(HIGHRES * 10 + instance, HIGHRES, t)) sendHighres(instance, vt, a, temp);
    const scaledId = SCALED[instance];
    if (opt.msg === 'scaled' && due(scaledId, scaledId, t)) sendScaled(instance, vt, a, temp);
    if (opt.msg === 'raw' && instance === opt.imu && due(RAW, RAW, t)) sendRaw(instance, vt, counts2, temp);
  }
}
// HIGHRES_IMU is asked per message, the instances share it (as on ArduPilot): `due` is keyed by
// message and instance so each instance keeps its own pace.
function setRate(id, hz) {
  rates.set(id, hz);
  if (id === HIGHRES || id === RAW) for (const i of [0, 1, 2]) nextDue.delete(id * 10 + i);
  nextDue.delete(id);
}

// ---- what the vehicle answers ----
const received = { frames: 0, crcErrors: 0, byMessage: {} };
function paramValue(name) {
  const p = params.get(name);
  const m = new common.ParamValue();
  m.paramId = name; m.paramValue = wireFloat(p); m.paramType = p.type;
  m.paramCount = paramNames.length; m.paramIndex = paramNames.indexOf(name);
  return m;
}
function handle(packet) {
  ++received.frames;
  const id = packet.header.msgid;
  received.byMessage[id] = (received.byMessage[id] || 0) + 1;
  const REG = { ...minimal.REGISTRY, ...common.REGISTRY };
  const clazz = REG[id];
  if (!clazz) return;
  const data = packet.protocol.data(packet.payload, clazz);
  if (id === 20 && !opt.noParams) {          // PARAM_REQUEST_READ
    if (params.has(data.paramId)) send(paramValue(data.paramId));
  } else if (id === 21 && !opt.noParams) {   // PARAM_REQUEST_LIST
    for (const n of paramNames) send(paramValue(n));
  } else if (id === 23 && !opt.noParams) {   // PARAM_SET
    const p = params.get(data.paramId);
    if (!p) return;
    p.value = fromWire(data.paramValue, p.type);
    if (data.paramId === opt.wrongEcho) p.value = Math.fround(p.value + 0.25);  // it keeps another value
    if (data.paramId !== opt.noEcho) send(paramValue(data.paramId));
  } else if (id === 76) {                    // COMMAND_LONG
    const command = data.command;
    const ack = new common.CommandAck();
    ack.command = command; ack.progress = 0; ack.resultParam2 = 0;
    ack.targetSystem = packet.header.sysid; ack.targetComponent = packet.header.compid;
    if (command === 511 && !opt.oldFirmware) {
      const msgid = Math.round(data._param1), interval = data._param2;
      if (msgid === HIGHRES && opt.msg !== 'highres') ack.result = 3;
      else { ack.result = 0; setRate(msgid, interval > 0 ? 1e6 / interval : 0); }
      console.error(`vehicle: SET_MESSAGE_INTERVAL ${msgid} ${interval} us -> result ${ack.result}`);
    } else {
      ack.result = 3;  // MAV_RESULT_UNSUPPORTED
      console.error(`vehicle: command ${command} unsupported`);
    }
    send(ack);
  } else if (id === 66) {                    // REQUEST_DATA_STREAM
    if (data.reqStreamId === 1 || data.reqStreamId === 0) {
      const hz = data.startStop ? data.reqMessageRate : 0;
      if (opt.msg === 'scaled') SCALED.forEach(s => setRate(s, hz));
      if (opt.msg === 'raw') setRate(RAW, hz);
      if (opt.msg === 'ardupilot') [RAW, SCALED[1], SCALED[2]].forEach(s => setRate(s, hz));
      console.error(`vehicle: REQUEST_DATA_STREAM ${data.reqStreamId} at ${hz} Hz`);
    }
  }
}
function reader() {
  const splitter = new MavLinkPacketSplitter({}, { onCrcError: () => { ++received.crcErrors; } });
  const parser = new MavLinkPacketParser();
  splitter.pipe(parser);
  parser.on('data', handle);
  return splitter;
}

// ---- links ----
let server = null;
const sockets = new Set();
function listenTcp(port) {
  server = net.createServer(socket => {
    sockets.add(socket);
    socket.setNoDelay(true);
    const out = b => { if (!socket.destroyed) socket.write(b); };
    outputs.add(out);
    const r = reader();
    socket.on('data', d => r.write(d));
    socket.on('error', () => {});
    socket.on('close', () => { outputs.delete(out); sockets.delete(socket); });
  });
  server.listen(port, '127.0.0.1', () => {
    if (port === 0 || opt.tcp === 0) console.log(`port ${server.address().port}`);
  });
}
if (opt.tcp !== null) listenTcp(opt.tcp);
if (opt.udpListen !== null || opt.udpTo !== null) {
  const sock = dgram.createSocket('udp4');
  let peer = opt.udpTo !== null ? { address: '127.0.0.1', port: opt.udpTo } : null;
  const r = reader();
  sock.on('message', (msg, rinfo) => { if (opt.udpListen !== null) peer = rinfo; r.write(msg); });
  outputs.add(b => { if (peer) sock.send(b, peer.port, peer.address); });
  sock.bind(opt.udpListen !== null ? opt.udpListen : 0, '127.0.0.1', () => {
    console.log(`port ${sock.address().port}`);
  });
}

// ---- heartbeat, reboot, silence ----
setInterval(() => {
  const h = new minimal.Heartbeat();
  h.type = 2;  // MAV_TYPE_QUADROTOR
  h.autopilot = ardupilot ? 3 : 12;
  h.baseMode = 0; h.customMode = 0; h.systemStatus = 3; h.mavlinkVersion = 3;
  send(h);
}, 1000);
if (opt.silentAfter !== null) setTimeout(() => { silent = true; console.error('vehicle: silent'); }, opt.silentAfter * 1000);
// The vehicle goes away for 2.5 s and comes back with its clock and sequence at 0.
function reboot() {
  if (rebooting) return;
  console.error('vehicle: rebooting');
  rebooting = true;
  if (server) { for (const so of sockets) so.destroy(); server.close(); }
  setTimeout(() => {
    rebooting = false; bootT = null; seq = 0; rates.clear(); nextDue.clear();
    if (opt.msg === 'scaled') SCALED.forEach(id => rates.set(id, opt.defaultRate));
    if (opt.msg === 'raw') rates.set(RAW, opt.defaultRate);
    if (opt.msg === 'ardupilot') [RAW, SCALED[1], SCALED[2]].forEach(id => rates.set(id, opt.defaultRate));
    if (server) listenTcp(rebootPort);
    console.error('vehicle: back after the reboot');
  }, 2500);
}
if (opt.rebootAt !== null) setTimeout(reboot, opt.rebootAt * 1000);
// SIGUSR1 reboots it now: a test picks the moment by what the wizard's screen shows, where a
// time would depend on how fast the machine runs the session.
process.on('SIGUSR1', reboot);
let rebootPort = opt.tcp;
if (server) server.on('listening', () => { rebootPort = server.address().port; });

// ---- samples in ----
const lines = readline.createInterface({ input: process.stdin });
lines.on('line', line => {
  if (line.startsWith('#') || !line.trim()) return;
  const f = line.trim().split(/[\s,]+/).map(Number);
  if (f.length < 4 || f.some(v => !Number.isFinite(v))) return;
  if (rebooting) return;
  streamSample(f[0], [f[1], f[2], f[3]], f.length > 4 ? f[4] : NaN);
});

function summary() {
  const s = { received, sent: counts, params: Object.fromEntries([...params].map(([n, p]) => [n, p.value])),
              wallS: (Date.now() - startWall) / 1000 };
  if (opt.summary) fs.writeFileSync(opt.summary, JSON.stringify(s, null, 1));
}
for (const sig of ['SIGTERM', 'SIGINT']) process.on(sig, () => { summary(); process.exit(0); });
process.on('exit', summary);
