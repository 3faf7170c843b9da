#!/usr/bin/env node
// Independent forward-kinematics cross-check of `throng bvh bake` against three.js's
// BVHLoader (Debian package libjs-three, three r111 UMD build). See README.md.
// Node >= 18, CommonJS, no npm packages.
'use strict';
const fs = require('fs');
const path = require('path');
const vm = require('vm');
const { execFileSync } = require('child_process');

const USAGE = 'usage: node tests/fk_crosscheck/check_fk.js --throng PATH_TO_THRONG_BINARY --bvh FILE.bvh\n' +
  '       [--position-channels replace|add] [--frames all|0,5,17] [--tolerance-rel 1e-5]';
const AXES = ['X', 'Y', 'Z'];
// Strict decimal / scientific notation. BVHLoader uses parseFloat, which silently reads
// "1,5" as 1 and "12abc" as 12; we refuse such tokens instead of letting both sides guess.
const NUM_RE = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;

function die(code, msg) { process.stderr.write(msg + '\n'); process.exit(code); }

function parseArgs(argv) {
  const o = { mode: 'replace', frames: null, tol: 1e-5, selfTest: false };
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    if (a === '--self-test') { o.selfTest = true; continue; }  // hidden: three.js path only
    if (a === '-h' || a === '--help') { console.log(USAGE); process.exit(0); }
    const v = argv[++i];
    if (v === undefined) die(2, `missing value for ${a}\n${USAGE}`);
    if (a === '--throng') o.throng = v;
    else if (a === '--bvh') o.bvh = v;
    else if (a === '--frames') o.frames = v;
    else if (a === '--position-channels' && (v === 'replace' || v === 'add')) o.mode = v;
    else if (a === '--tolerance-rel' && Number(v) >= 0) o.tol = Number(v);
    else die(2, `bad argument: ${a} ${v}\n${USAGE}`);
  }
  if (!o.bvh || (!o.selfTest && !o.throng)) die(2, USAGE);
  return o;
}

function loadThree() {
  const dir = process.env.THREE_JS_DIR || '/usr/share/javascript/three';
  const threeFile = path.join(dir, 'build', 'three.js');
  const loaderFile = path.join(dir, 'examples', 'js', 'loaders', 'BVHLoader.js');
  for (const f of [threeFile, loaderFile]) {
    if (!fs.existsSync(f)) {
      die(2, `three.js not found: ${f} is missing.\nInstall the Debian package libjs-three ` +
        '(apt-get install libjs-three) or point THREE_JS_DIR at a three.js r111 tree.');
    }
  }
  const THREE = require(threeFile);  // UMD: takes its CommonJS branch, module.exports = THREE
  // BVHLoader.js's UMD wrapper does require('./three') relative to itself, which does not
  // exist in the Debian layout: run it as a CommonJS module body whose require hands it THREE.
  const mod = { exports: {} };
  const body = fs.readFileSync(loaderFile, 'utf8');
  const fn = vm.runInThisContext('(function (exports, require, module) {' + body + '\n})',
    { filename: loaderFile });
  fn.call(mod.exports, mod.exports, (n) => (n === './three' ? THREE : require(n)), mod);
  if (typeof mod.exports.BVHLoader !== 'function') die(2, `${loaderFile} did not export BVHLoader`);
  // KeyframeTracks store values as Float32Array by default; BVHLoader itself computes in
  // float64. Keep float64 so the cross-check is not limited by track storage precision.
  THREE.KeyframeTrack.prototype.ValueBufferType = Float64Array;
  return { THREE, BVHLoader: mod.exports.BVHLoader };
}

// Our own structural parse of the BVH. Used to (a) re-emit a canonical text layout that
// BVHLoader's line-oriented reader cannot trip over, (b) know which bones are End Sites,
// (c) a hand FK for --self-test. Numbers are kept as the original strings.
function parseBvh(text) {
  const lines = text.replace(/^\uFEFF/, '').split(/\r\n|\r|\n/);
  const mi = lines.findIndex((l) => /^\s*MOTION\s*$/i.test(l));
  if (mi < 0) throw new Error('no MOTION line');
  // Braces become separate tokens so "ROOT Hips {" or "{ OFFSET ..." also work.
  const toks = lines.slice(0, mi).join('\n').replace(/[{}]/g, ' $& ').split(/\s+/).filter(Boolean);
  let p = 0;
  const next = (what) => {
    if (p >= toks.length) throw new Error(`hierarchy ends early, expected ${what}`);
    return toks[p++];
  };
  const num = (t) => { if (!NUM_RE.test(t)) throw new Error(`bad number '${t}'`); return t; };
  if (next('HIERARCHY').toUpperCase() !== 'HIERARCHY') throw new Error('HIERARCHY expected');
  const nodes = [];  // DFS pre-order, End Sites included: the order BVHLoader builds bones in
  function readNode(kind, parent) {
    const node = { endSite: kind === 'END', parent, offset: null, channels: [], children: [] };
    nodes.push(node);
    if (node.endSite) {
      if (next('Site').toUpperCase() !== 'SITE') throw new Error("'End' not followed by 'Site'");
      node.name = 'End Site';
    } else node.name = next('joint name');
    const brace = next('{');
    if (brace !== '{') {
      throw new Error(`joint '${node.name} ${brace}': names with whitespace are unsupported ` +
        '(BVHLoader keeps only the first word)');
    }
    for (;;) {
      const t = next('}');
      const T = t.toUpperCase();
      if (t === '}') break;
      if (T === 'OFFSET') node.offset = [num(next('x')), num(next('y')), num(next('z'))];
      else if (T === 'CHANNELS' && !node.endSite) {
        const n = Number(next('channel count'));
        if (!Number.isInteger(n) || n < 0) throw new Error(`bad CHANNELS count in ${node.name}`);
        for (let k = 0; k < n; k++) {
          const c = next('channel name').toLowerCase();
          const m = /^([xyz])(position|rotation)$/.exec(c);
          // BVHLoader matches channel names case-sensitively and does NOT consume a value
          // for an unknown one (shifting all later data), so canonicalise the spelling.
          if (!m) throw new Error(`unknown channel '${c}' in ${node.name}`);
          node.channels.push(m[1].toUpperCase() + m[2]);
        }
      } else if ((T === 'JOINT' || T === 'END') && !node.endSite) node.children.push(readNode(T, node));
      else throw new Error(`unexpected '${t}' in ${node.name}`);
    }
    if (!node.offset) throw new Error(`no OFFSET in ${node.name}`);
    return node;
  }
  if (next('ROOT').toUpperCase() !== 'ROOT') throw new Error('ROOT expected');
  const root = readNode('ROOT', null);
  if (p < toks.length) throw new Error(`unexpected '${toks[p]}' after the root (only one ROOT is supported by BVHLoader)`);

  // MOTION: "Frames: N", "Frame Time: T", then all values, re-chunked per frame below.
  const rest = lines.slice(mi + 1).map((l) => l.trim()).filter((l) => l.length);
  const fm = /^Frames\s*:\s*(\d+)$/i.exec(rest[0] || '');
  const tm = /^Frame\s*Time\s*:\s*(\S+)$/i.exec(rest[1] || '');
  if (!fm || !tm) throw new Error("expected 'Frames: N' and 'Frame Time: T' after MOTION");
  const frameCount = Number(fm[1]);
  if (frameCount < 1) throw new Error('no frames');
  const vals = rest.slice(2).join(' ').split(/\s+/).filter(Boolean);
  const nch = nodes.reduce((s, n) => s + n.channels.length, 0);
  if (vals.length !== frameCount * nch) {
    throw new Error(`motion has ${vals.length} values, expected ${frameCount} frames x ${nch} channels`);
  }
  vals.forEach(num);
  const joints = nodes.filter((n) => !n.endSite);
  return { root, nodes, joints, parents: joints.map((j) => joints.indexOf(j.parent)),
    frameCount, frameTime: num(tm[1]), nch, vals };
}

// Canonical BVH text for BVHLoader: one item per line, single spaces, LF, uppercase keywords,
// OFFSET before CHANNELS, one frame per line. In 'replace' mode the OFFSET component of every
// axis that has a position channel is written as 0: BVHLoader computes offset + channel, so
// with a zero offset it yields exactly the channel value (see README.md).
function canonicalBvh(bvh, mode) {
  const out = ['HIERARCHY'];
  (function emit(node) {
    const off = node.offset.slice();
    if (mode === 'replace') AXES.forEach((a, k) => { if (node.channels.includes(a + 'position')) off[k] = '0'; });
    out.push(node.endSite ? 'End Site' : (node.parent ? 'JOINT ' : 'ROOT ') + node.name, '{', 'OFFSET ' + off.join(' '));
    if (!node.endSite) out.push(['CHANNELS', node.channels.length].concat(node.channels).join(' '));
    node.children.forEach(emit);
    out.push('}');
  })(bvh.root);
  out.push('MOTION', 'Frames: ' + bvh.frameCount, 'Frame Time: ' + bvh.frameTime);
  for (let f = 0; f < bvh.frameCount; f++) out.push(bvh.vals.slice(f * bvh.nch, (f + 1) * bvh.nch).join(' '));
  return out.join('\n') + '\n';
}

// World positions of every joint (End Sites excluded) at the given frames, via three.js.
function threeFK(libs, bvh, mode, frames) {
  const msgs = [];
  const saved = [console.error, console.warn];
  console.error = console.warn = (...a) => msgs.push(a.join(' '));  // BVHLoader only logs errors
  let res;
  try { res = new libs.BVHLoader().parse(canonicalBvh(bvh, mode)); } catch (e) { msgs.push(String(e)); }
  finally { [console.error, console.warn] = saved; }
  if (msgs.length) die(2, 'BVHLoader failed: ' + msgs.join('; '));
  const bones = res.skeleton.bones;
  if (bones.length !== bvh.nodes.length) die(2, `BVHLoader made ${bones.length} bones, expected ${bvh.nodes.length}`);
  // BVHLoader also makes a Bone (named 'ENDSITE', without tracks) for every End Site: drop them.
  const jb = bones.filter((b, i) => !bvh.nodes[i].endSite);
  const tracks = res.clip.tracks;  // per joint, in BVH order: .position then .quaternion
  const problems = [];
  if (tracks.length !== 2 * jb.length) problems.push(`${tracks.length} tracks for ${jb.length} joints`);
  jb.forEach((b, j) => {
    const name = bvh.joints[j].name;
    const par = b.parent && b.parent.isBone ? jb.indexOf(b.parent) : -1;
    if (b.name !== name) problems.push(`joint ${j} named '${b.name}', expected '${name}'`);
    if (par !== bvh.parents[j]) problems.push(`joint ${name} parent ${par}, expected ${bvh.parents[j]}`);
    const [pt, qt] = [tracks[2 * j], tracks[2 * j + 1]];
    if (!pt || pt.name !== `.bones[${name}].position` || !qt || qt.name !== `.bones[${name}].quaternion` ||
        pt.times.length !== bvh.frameCount || qt.times.length !== bvh.frameCount) {
      problems.push(`unexpected tracks for joint ${name}`);
    }
  });
  if (problems.length) die(2, 'BVHLoader result does not match the BVH: ' + problems.slice(0, 5).join('; '));
  // Read keyframe f straight from the track arrays (no mixer interpolation), pose, update.
  const out = {};
  for (const f of frames) {
    jb.forEach((b, j) => {
      b.position.fromArray(tracks[2 * j].values, 3 * f);
      b.quaternion.fromArray(tracks[2 * j + 1].values, 4 * f);
    });
    jb[0].updateMatrixWorld(true);
    out[f] = jb.map((b) => [b.matrixWorld.elements[12], b.matrixWorld.elements[13], b.matrixWorld.elements[14]]);
  }
  return out;
}

// Hand-rolled FK (self-test only): world = parentWorld * T(t) * R(c1) * R(c2) * R(c3),
// rotations multiplied in CHANNELS order, column vectors, degrees.
function handFK(bvh, mode, f) {
  const mul = (A, B) => A.map((r) => [0, 1, 2].map((c) => r[0] * B[0][c] + r[1] * B[1][c] + r[2] * B[2][c]));
  const rot = (k, deg) => {
    const a = (deg * Math.PI) / 180, c = Math.cos(a), s = Math.sin(a);
    const [i, j] = [(k + 1) % 3, (k + 2) % 3];
    const R = [[1, 0, 0], [0, 1, 0], [0, 0, 1]];
    R[i][i] = c; R[i][j] = -s; R[j][i] = s; R[j][j] = c;
    return R;
  };
  let v = f * bvh.nch;
  const world = new Map();
  return bvh.joints.map((jn) => {
    const off = jn.offset.map(Number), t = off.slice();
    let R = [[1, 0, 0], [0, 1, 0], [0, 0, 1]];
    for (const c of jn.channels) {
      const k = AXES.indexOf(c[0]), x = Number(bvh.vals[v++]);
      if (c.endsWith('position')) t[k] = mode === 'add' ? off[k] + x : x;
      else R = mul(R, rot(k, x));
    }
    const P = world.get(jn.parent) || { R: [[1, 0, 0], [0, 1, 0], [0, 0, 1]], p: [0, 0, 0] };
    const p = P.R.map((r, i) => P.p[i] + r[0] * t[0] + r[1] * t[1] + r[2] * t[2]);
    world.set(jn, { R: mul(P.R, R), p });
    return p;
  });
}

// Max |difference| over all frames/joints/axes, and the skeleton's Y extent in `ref`.
function compare(ref, test, frames) {
  const w = { err: -1 };
  let ymin = Infinity, ymax = -Infinity;
  for (const f of frames) {
    ref[f].forEach((r, j) => {
      ymin = Math.min(ymin, r[1]); ymax = Math.max(ymax, r[1]);
      for (let k = 0; k < 3; k++) {
        const t = test[f][j][k], d = Math.abs(r[k] - (typeof t === 'number' ? t : NaN));
        if (!(d <= w.err)) Object.assign(w, { err: Number.isNaN(d) ? Infinity : d, f, j, k });
      }
    });
  }
  return { worst: w, height: ymax - ymin };
}

function selectFrames(spec, n) {
  if (spec === 'all') return Array.from({ length: n }, (_, i) => i);
  if (spec) {
    const fs_ = spec.split(',').map((s) => s.trim());
    if (!fs_.every((s) => /^\d+$/.test(s) && Number(s) < n)) die(2, `--frames: need 'all' or indices 0..${n - 1}, got '${spec}'`);
    return [...new Set(fs_.map(Number))];
  }
  // Default: first, last and 8 evenly spaced frames in between.
  return [...new Set(Array.from({ length: 10 }, (_, i) => Math.round((i * (n - 1)) / 9)))];
}

function main() {
  const o = parseArgs(process.argv.slice(2));
  const libs = loadThree();
  let bvh;
  try { bvh = parseBvh(fs.readFileSync(o.bvh, 'utf8')); } catch (e) { die(2, `${o.bvh}: ${e.message}`); }
  const frames = selectFrames(o.frames, bvh.frameCount);
  const names = bvh.joints.map((j) => j.name);
  const fmt = (x) => x.toPrecision(6);
  const p10 = (x) => (typeof x === 'number' ? x.toPrecision(10) : String(x));

  if (o.selfTest) {  // three.js vs hand FK over all frames; print a few joints of frames 0 and 1
    const all = selectFrames('all', bvh.frameCount);
    const three = threeFK(libs, bvh, o.mode, all);
    const show = [...new Set([0, 1, names.length - 1])].filter((j) => j < names.length);
    for (const f of all.slice(0, 2)) for (const j of show) console.log(`frame ${f} ${names[j]}: ${three[f][j].map(fmt).join(' ')}`);
    const hand = {};
    for (const f of all) hand[f] = handFK(bvh, o.mode, f);
    const { worst, height } = compare(three, hand, all);
    const ok = worst.err <= o.tol * height;
    console.log(`self-test ${o.bvh} mode=${o.mode} frames=${all.length} joints=${names.length} ` +
      `max_abs_err(three-vs-hand)=${worst.err.toExponential(3)} height=${fmt(height)} ${ok ? 'PASS' : 'FAIL'}`);
    process.exit(ok ? 0 : 1);
  }

  const args = ['bvh', 'bake', o.bvh, '--json', '-', '--frames', frames.join(',')];
  if (o.mode !== 'replace') args.push('--position-channels', o.mode);
  let stdout;
  try {
    stdout = execFileSync(o.throng, args, { maxBuffer: 1 << 30, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
  } catch (e) {
    die(2, `throng failed (${e.status != null ? 'exit ' + e.status : e.code || e.signal}): ${o.throng} ${args.join(' ')}\n${e.stderr || e.message}`);
  }
  let js;
  try { js = JSON.parse(stdout); } catch (e) { die(2, `throng printed invalid JSON: ${e.message}`); }

  // Structure must agree before positions mean anything.
  const bad = (m) => { console.log(`fk-crosscheck ${o.bvh} mode=${o.mode} STRUCTURE MISMATCH: ${m} FAIL`); process.exit(1); };
  for (const [key, want] of [['joints', names], ['parents', bvh.parents]]) {
    const got = js[key];
    if (!Array.isArray(got)) bad(`no "${key}" array in throng output`);
    const i = want.findIndex((x, k) => got[k] !== x);
    if (i >= 0 || got.length !== want.length) {
      bad(`${key} differ (throng has ${got.length}, BVH/three.js ${want.length})` +
        (i >= 0 ? `; first at joint #${i}: throng ${JSON.stringify(got[i])} vs ${JSON.stringify(want[i])}` : ''));
    }
  }
  if (js.frame_count !== undefined && js.frame_count !== bvh.frameCount) bad(`frame_count ${js.frame_count} vs ${bvh.frameCount}`);
  const test = {};
  for (const f of frames) {
    const fr = js.frames && js.frames[String(f)];
    if (!Array.isArray(fr) || fr.length !== names.length || !fr.every((p) => Array.isArray(p) && p.length === 3)) {
      bad(`frame ${f} missing or not ${names.length} [x,y,z] positions`);
    }
    test[f] = fr;
  }

  const three = threeFK(libs, bvh, o.mode, frames);
  const cmp = compare(three, test, frames);
  const height = Number.isFinite(js.height) && js.height > 0 ? js.height : cmp.height;
  const w = cmp.worst;
  const ok = w.err <= o.tol * height;
  console.log(`fk-crosscheck ${o.bvh} mode=${o.mode} frames=${frames.length} joints=${names.length} ` +
    `max_abs_err=${w.err.toExponential(3)} height=${fmt(height)} rel=${(w.err / height).toExponential(3)} ${ok ? 'PASS' : 'FAIL'}`);
  if (!ok) {
    console.log(`worst: joint ${names[w.j]} (#${w.j}) frame ${w.f} axis ${AXES[w.k]}: ` +
      `throng=[${test[w.f][w.j].map(p10).join(', ')}] three.js=[${three[w.f][w.j].map(p10).join(', ')}] ` +
      `tolerance=${(o.tol * height).toExponential(3)}`);
  }
  process.exit(ok ? 0 : 1);
}

main();
