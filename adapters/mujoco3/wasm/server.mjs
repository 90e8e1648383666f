// The WebAssembly side of engine "mujoco3" (issue 33): MuJoCo 3.3.8 from the
// pinned mujoco-js package, driven by the C++ adapter over stdin/stdout. It
// runs MuJoCo's step and reports what MuJoCo computed; it decides nothing:
// each contact's solref comes back from the C++ side (the same rule as the
// 2.2.2 adapter's, written once there: mujoco_solref_rule.hpp).
//
// Frames, both ways: u32 kind, u32 payload bytes, payload (little-endian;
// numbers as float64). A step is mj_step's own sequence (engine_forward.c,
// 3.3.8: mj_checkPos, mj_checkVel, mj_forward, mj_checkAcc, then the
// integrator) with mj_fwdPosition's stages called one by one, so that the
// contacts of mj_collision can be sent out and re-added with their solref
// before mj_makeConstraint (this build has no mjcb_ callbacks, and
// d.contact.get(i) is a copy: the route is copy, d.ncon = 0, mj_addContact).
// The C++ side is asked only at a step where a contact is included (exclude
// 0: distance below 0, in the constraint); the other steps' solrefs are
// those MuJoCo copied from the pairs. Every step's outcome goes back in
// batches: a pipe's round trip costs far more than a step.
//   C++ -> here                          here -> C++
//   0 VERSION                            1 INFO  JSON: versions / model sizes
//   1 LOAD   MJCF text                   2 BATCH records, then the question
//   2 START  qpos, qvel: the state at    9 ERROR text
//            t = 0, run to it (0 steps)
//   3 SOLREFS pair_solref[2 npair], per contact solref[2], exclude
//   4 RUN    n: n more steps
//   5 QUIT
//   6 STATS                              1 INFO  JSON: the arena's size and use
// BATCH: count, count records, then asking (0 or 1) and, when 1, the
// question: warnings, qpos, qvel, ncon, contacts (16 numbers each: geom1,
// geom2, dist, pos[3], frame[9], exclude). The C++ side answers SOLREFS and
// the run goes on to the next BATCH. A record is one step's outcome after the
// constraint solve: asked (0, 1), warnings (numbers[8], lastinfo[8]), qpos,
// qvel, ncon, then per contact those 16 numbers, efc_address and
// mj_contactForce's 6 (23 numbers).
import fs from 'node:fs';
import loadMujoco from 'mujoco-js';

const kNumWarnings = 8;  // mjNWARNING (mjtWarning, mjdata.h 3.3.8)

function readExactly(n) {
  const buf = Buffer.alloc(n);
  let got = 0;
  while (got < n) {
    const r = fs.readSync(0, buf, got, n - got, null);
    if (r === 0) process.exit(0);  // the C++ side closed the pipe
    got += r;
  }
  return buf;
}

function readFrame() {
  const head = readExactly(8);
  const kind = head.readUInt32LE(0);
  const bytes = head.readUInt32LE(4);
  return { kind, payload: bytes > 0 ? readExactly(bytes) : Buffer.alloc(0) };
}

function writeFrame(kind, payload) {
  const head = Buffer.alloc(8);
  head.writeUInt32LE(kind, 0);
  head.writeUInt32LE(payload.length, 4);
  const all = Buffer.concat([head, payload]);
  let off = 0;
  while (off < all.length) off += fs.writeSync(1, all, off, all.length - off);
}

function writeNumbers(kind, values) {
  writeFrame(kind, Buffer.from(new Float64Array(values).buffer));
}

function numbers(payload) {
  const out = new Float64Array(payload.length / 8);
  for (let i = 0; i < out.length; i++) out[i] = payload.readDoubleLE(8 * i);
  return out;
}

// stdout carries the frames only: MuJoCo's own texts (mju_warning prints
// through Emscripten's print) and any console.log go to stderr, where the C++
// side reads them as the library's words
console.log = console.error;
const toStderr = (text) => process.stderr.write(`${text}\n`);
const mj = await loadMujoco({ print: toStderr, printErr: toStderr });
let m = null;
let d = null;
let integrator = 'Euler';
const force = new mj.DoubleBuffer(6);

function warnings(out) {
  const w = d.warning;
  const number = [];
  const info = [];
  for (let i = 0; i < kNumWarnings; i++) {
    const s = w.get(i);
    number.push(s.number);
    info.push(s.lastinfo);
    s.delete();
  }
  w.delete();
  append(out, number);
  append(out, info);
}

// appends every number of `values` to `out`: a loop, not push(...values),
// whose arguments live on the stack (a 1000-body scene's record is 1e5
// numbers, past V8's limit)
function append(out, values) {
  for (let i = 0; i < values.length; i++) out.push(values[i]);
}

function pushContact(out, c) {
  out.push(c.geom1, c.geom2, c.dist, ...c.pos, ...c.frame, c.exclude);
}

// mj_step up to mj_collision (checks, mj_fwdPosition's first stages); the
// C++ side's solrefs for the contacts in the constraint, if any; the rest of
// mj_forward and mj_checkAcc; the step's record into `records`
function forward(records) {
  mj.mj_checkPos(m, d);
  mj.mj_checkVel(m, d);
  mj.mj_kinematics(m, d);
  mj.mj_comPos(m, d);
  mj.mj_camlight(m, d);
  mj.mj_flex(m, d);
  mj.mj_tendon(m, d);
  mj.mj_makeM(m, d);
  mj.mj_factorM(m, d);
  mj.mj_collision(m, d);
  const n = d.ncon;
  let asked = 0;
  if (n > 0) {
    const list = d.contact;
    const held = [];
    let included = false;
    for (let i = 0; i < n; i++) {
      const c = list.get(i);
      held.push(c);
      if (c.exclude === 0) included = true;
    }
    list.delete();
    if (included) {
      asked = 1;
      const question = [];
      warnings(question);
      append(question, d.qpos);
      append(question, d.qvel);
      question.push(n);
      for (const c of held) pushContact(question, c);
      sendBatch(records, question);
      records.length = 0;
      const { kind, payload } = readFrame();
      if (kind !== 3) throw new Error(`expected SOLREFS, got command ${kind}`);
      const v = numbers(payload);
      let at = 0;
      const pairSolref = m.pair_solref;
      for (let p = 0; p < 2 * m.npair; p++) pairSolref[p] = v[at++];
      d.ncon = 0;
      for (const c of held) {
        c.solref[0] = v[at++];
        c.solref[1] = v[at++];
        c.exclude = v[at++];
        mj.mj_addContact(m, d, c);
      }
    }
    for (const c of held) c.delete();
  }
  mj.mj_makeConstraint(m, d);
  mj.mj_island(m, d);
  mj.mj_transmission(m, d);
  mj.mj_projectConstraint(m, d);
  mj.mj_fwdVelocity(m, d);
  mj.mj_fwdActuation(m, d);
  mj.mj_fwdAcceleration(m, d);
  mj.mj_fwdConstraint(m, d);
  mj.mj_checkAcc(m, d);
  const rec = [asked];
  warnings(rec);
  append(rec, d.qpos);
  append(rec, d.qvel);
  const k = d.ncon;
  rec.push(k);
  if (k > 0) {
    const list = d.contact;
    for (let i = 0; i < k; i++) {
      const c = list.get(i);
      pushContact(rec, c);
      const address = c.efc_address;
      c.delete();
      rec.push(address);
      if (address >= 0) {
        mj.mj_contactForce(m, d, i, force);
        rec.push(...force.GetView());
      } else {
        rec.push(0, 0, 0, 0, 0, 0);
      }
    }
    list.delete();
  }
  records.push(rec);
}

// BATCH: the records so far, then the question (none: asking 0)
function sendBatch(records, question) {
  const out = [records.length];
  for (const r of records) append(out, r);
  if (question) {
    out.push(1);
    append(out, question);
  } else {
    out.push(0);
  }
  writeNumbers(2, out);
}

function integrate() {
  if (integrator === 'RK4') {
    mj.mj_RungeKutta(m, d, 4);
  } else if (integrator === 'implicit' || integrator === 'implicitfast') {
    mj.mj_implicit(m, d);
  } else {
    mj.mj_Euler(m, d);
  }
}

// n more steps, each integrate then forward (the state a step starts from is
// forwarded already); n = 0 forwards the current state (START)
function run(n) {
  const records = [];
  if (n === 0) forward(records);
  for (let i = 0; i < n; i++) {
    integrate();
    forward(records);
  }
  sendBatch(records, null);
}

function load(xml) {
  if (d) d.delete();
  if (m) m.delete();
  d = null;
  m = null;
  mj.FS.writeFile('/case.xml', xml);
  try {
    m = mj.MjModel.loadFromXML('/case.xml');
  } catch (e) {
    // this build's mjXError carries no text (getExceptionMessage faults)
    writeFrame(9, Buffer.from(`MuJoCo ${mj.mj_versionString()} refused the model (its XML `
      + `parser gives no message in this build): ${e && e.name ? e.name : e}`));
    return;
  }
  d = new mj.MjData(m);
  const match = /integrator="([A-Za-z0-9]+)"/.exec(xml);
  integrator = match ? match[1] : 'Euler';
  writeFrame(1, Buffer.from(JSON.stringify({
    version: mj.mj_versionString(), nq: m.nq, nv: m.nv, ngeom: m.ngeom, nbody: m.nbody,
    npair: m.npair, integrator,
  })));
}

for (;;) {
  const { kind, payload } = readFrame();
  if (kind === 5) break;
  if (kind === 1) {
    load(payload.toString('utf8'));
  } else if (kind === 0) {
    const pkg = JSON.parse(fs.readFileSync(
      new URL('./node_modules/mujoco-js/package.json', import.meta.url), 'utf8'));
    writeFrame(1, Buffer.from(JSON.stringify({
      version: mj.mj_versionString(), package: pkg.version, node: process.version,
    })));
  } else if (!m) {
    writeFrame(9, Buffer.from(`command ${kind} before a model was loaded`));
  } else if (kind === 2) {
    const v = numbers(payload);
    const qpos = d.qpos;
    for (let i = 0; i < m.nq; i++) qpos[i] = v[i];
    const qvel = d.qvel;
    for (let i = 0; i < m.nv; i++) qvel[i] = v[m.nq + i];
    run(0);
  } else if (kind === 4) {
    run(numbers(payload)[0]);
  } else if (kind === 6) {
    // the arena (contacts, rows, the solver's stack) and the most of it used
    writeFrame(1, Buffer.from(JSON.stringify({
      narena_bytes: Number(m.narena), maxuse_arena_bytes: Number(d.maxuse_arena),
      most_contacts: d.maxuse_con, most_rows: d.maxuse_efc,
    })));
  } else {
    writeFrame(9, Buffer.from(`unknown command ${kind}`));
  }
}
force.delete();
if (d) d.delete();
if (m) m.delete();
process.exit(0);
