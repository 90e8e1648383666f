// The facts the mujoco3 engine (issue 33) builds on, measured on the pinned
// mujoco-js (MuJoCo's official WebAssembly build): its version, and that a
// contact's solref can be set between collision and the constraint solve.
// MuJoCo 3 in this build has no mjcb_* callbacks, and d.contact.get(i)
// returns a copy: the route is mj_collision, copy and edit each contact,
// d.ncon = 0, mj_addContact each, then the rest of mj_fwdPosition and the
// step (MuJoCo's engine_forward.c order). Prints one JSON line:
//   version      mj_versionString()
//   qpos_hex     the final qpos of a 1 kg ball (radius 0.1 m, slide x, z and
//                hinge y, thrown at 1 m/s along x) after 1 s at h = 1e-4 on a
//                plane, every contact's solref set to [solref, 1] by that
//                route: IEEE-754 hex, to compare bits across runs
//   kbip_k       the contact row's stiffness MuJoCo derived from it (efc_KBIP)
//   normal_n     mj_contactForce's normal force at the end, N (rest: m g)
// Usage: node probe.mjs [solref timeconst, default 0.02]
import loadMujoco from 'mujoco-js';

const timeconst = Number(process.argv[2] ?? '0.02');
const mj = await loadMujoco();
mj.FS.writeFile('/ball.xml', `<mujoco><option timestep="1e-4"/><worldbody>
 <geom name="floor" type="plane" size="5 5 .1"/>
 <body pos="0 0 .1"><joint type="slide" axis="1 0 0"/><joint type="slide" axis="0 0 1"/>
  <joint type="hinge" axis="0 1 0"/><geom name="ball" type="sphere" size=".1" mass="1" friction=".5"/></body>
</worldbody></mujoco>`);
const m = mj.MjModel.loadFromXML('/ball.xml');
const d = new mj.MjData(m);
d.qvel[0] = 1.0;
for (let i = 0; i < 10000; i++) {
  mj.mj_kinematics(m, d); mj.mj_comPos(m, d); mj.mj_camlight(m, d); mj.mj_flex(m, d);
  mj.mj_tendon(m, d); mj.mj_makeM(m, d); mj.mj_factorM(m, d); mj.mj_collision(m, d);
  if (d.ncon > 0) {
    const list = d.contact;
    const copies = [];
    for (let c = 0; c < d.ncon; c++) {
      const k = list.get(c);
      k.solref[0] = timeconst;
      k.solref[1] = 1.0;
      copies.push(k);
    }
    list.delete();
    d.ncon = 0;
    for (const k of copies) { mj.mj_addContact(m, d, k); k.delete(); }
  }
  mj.mj_makeConstraint(m, d); mj.mj_island(m, d); mj.mj_transmission(m, d);
  mj.mj_projectConstraint(m, d); mj.mj_fwdVelocity(m, d); mj.mj_fwdActuation(m, d);
  mj.mj_fwdAcceleration(m, d); mj.mj_fwdConstraint(m, d); mj.mj_Euler(m, d);
}
const hex = (v) => Buffer.from(new Float64Array([v]).buffer).reverse().toString('hex');
// a DoubleBuffer lives in the module's memory: a plain Float64Array would be
// taken as an address there
const f = new mj.DoubleBuffer(6);
let normal = null;
if (d.ncon > 0) { mj.mj_contactForce(m, d, 0, f); normal = f.GetView()[0]; }
console.log(JSON.stringify({
  version: mj.mj_versionString(),
  qpos_hex: Array.from(d.qpos, hex),
  kbip_k: d.nefc > 0 ? d.efc_KBIP[0] : null,
  normal_n: normal,
}));
f.delete(); d.delete(); m.delete();
