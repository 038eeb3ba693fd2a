// Runs OIDN's "rt" U-Net with TensorFlow.js (CPU backend) on a raw 9-channel image, with
// OIDN's own input/output processing (core/color.h, cpu_input_process.ispc, autoexposure).
// Written for glint's tests (tests/denoise/data/README.md says how it was run).
// usage: node oidn_tfjs.js weights.tza input.bin output.bin [relu or relu6]
const fs = require('fs');
const tf = require('@tensorflow/tfjs');
const [,, tzaPath, inPath, outPath, act = 'relu'] = process.argv;

function readTza(path) {
  const buf = fs.readFileSync(path);
  const ab = buf.buffer.slice(buf.byteOffset, buf.byteOffset + buf.length);
  const view = new DataView(ab);
  if (view.getUint16(0, true) !== 0x41d7 || view.getUint8(2) !== 2) throw new Error('bad tza');
  let off = Number(view.getBigUint64(4, true));
  const n = view.getUint32(off, true); off += 4;
  const map = new Map();
  for (let i = 0; i < n; ++i) {
    const len = view.getUint16(off, true); off += 2;
    const name = buf.toString('latin1', off, off + len); off += len;
    const nd = view.getUint8(off++);
    const shape = [];
    for (let j = 0; j < nd; ++j) { shape.push(view.getUint32(off, true)); off += 4; }
    off += nd; // layout
    const type = String.fromCharCode(view.getUint8(off++));
    const dataOff = Number(view.getBigUint64(off, true)); off += 8;
    const count = shape.reduce((a, b) => a * b, 1);
    const vals = new Float32Array(count);
    for (let k = 0; k < count; ++k)
      vals[k] = type === 'h' ? half(view.getUint16(dataOff + 2 * k, true)) : view.getFloat32(dataOff + 4 * k, true);
    let t = tf.tensor(vals, shape);
    if (nd === 4) t = t.transpose([2, 3, 1, 0]);  // OIHW -> HWIO
    map.set(name, t);
  }
  return map;
}
function half(h) {
  const s = h & 0x8000 ? -1 : 1, e = (h >> 10) & 0x1f, f = h & 0x3ff;
  if (e === 0) return s * Math.pow(2, -14) * (f / 1024);
  if (e === 31) return f ? NaN : s * Infinity;
  return s * Math.pow(2, e - 15) * (1 + f / 1024);
}
const f32 = Math.fround;
const PU = {a: f32(1.41283765e+03), b: f32(1.64593172e+00), c: f32(4.31384981e-01), d: f32(-2.94139609e-03),
  e: f32(1.92653254e-01), f: f32(6.26026094e-03), g: f32(9.98620152e-01), y0: f32(1.57945760e-06),
  y1: f32(3.22087631e-02), x0: f32(2.23151711e-03), x1: f32(3.70974749e-01)};
const puF = y => y <= PU.y0 ? PU.a * y : y <= PU.y1 ? PU.b * Math.pow(y, PU.c) + PU.d : PU.e * Math.log(y + PU.f) + PU.g;
const puI = x => x <= PU.x0 ? x / PU.a : x <= PU.x1 ? Math.pow((x - PU.d) / PU.b, 1 / PU.c) : Math.exp((x - PU.g) / PU.e) - PU.f;
const norm = 1 / puF(65504);
const lum = (r, g, b) => 0.212671 * r + 0.715160 * g + 0.072169 * b;
const nz = v => Number.isFinite(v) ? v : 0;
const clamp = (v, lo, hi) => Math.min(Math.max(v, lo), hi);

const raw = fs.readFileSync(inPath);
const W = raw.readInt32LE(0), H = raw.readInt32LE(4), C = raw.readInt32LE(8);
const px = new Float32Array(raw.buffer.slice(raw.byteOffset + 12, raw.byteOffset + 12 + W * H * C * 4));
const at = (x, y, c) => px[(y * W + x) * C + c];

// Autoexposure: bins of at most 16x16, geometric mean of the bins' mean luminance -> 0.18.
function autoexposure() {
  const nbh = Math.ceil(H / 16), nbw = Math.ceil(W / 16);
  let sum = 0, count = 0;
  for (let i = 0; i < nbh; ++i) for (let j = 0; j < nbw; ++j) {
    const h0 = Math.floor(i * H / nbh), h1 = Math.floor((i + 1) * H / nbh);
    const w0 = Math.floor(j * W / nbw), w1 = Math.floor((j + 1) * W / nbw);
    let L = 0;
    for (let y = h0; y < h1; ++y) for (let x = w0; x < w1; ++x)
      L += lum(Math.max(nz(at(x, y, 0)), 0), Math.max(nz(at(x, y, 1)), 0), Math.max(nz(at(x, y, 2)), 0));
    L /= (h1 - h0) * (w1 - w0);
    if (L > 1e-8) { sum += Math.log2(L); count++; }
  }
  return count > 0 ? 0.18 / Math.pow(2, sum / count) : 1;
}
const exposure = f32(autoexposure());
const Hp = Math.ceil(H / 16) * 16, Wp = Math.ceil(W / 16) * 16;
const input = new Float32Array(Hp * Wp * 9);  // zero padded at bottom/right, NHWC
for (let y = 0; y < H; ++y) for (let x = 0; x < W; ++x) {
  const o = (y * Wp + x) * 9;
  for (let c = 0; c < 3; ++c) input[o + c] = puF(clamp(nz(at(x, y, c) * exposure), 0, 3.4e38)) * norm;
  for (let c = 0; c < 3; ++c) input[o + 3 + c] = clamp(nz(at(x, y, 3 + c)), 0, 1);
  for (let c = 0; c < 3; ++c) input[o + 6 + c] = clamp(nz(at(x, y, 6 + c)), -1, 1) * 0.5 + 0.5;
}

const w = readTza(tzaPath);
const conv = (name, x) => tf.layers.conv2d({filters: w.get(name + '.weight').shape[3], kernelSize: 3,
  padding: 'same', activation: act, weights: [w.get(name + '.weight'), w.get(name + '.bias')]}).apply(x);
const pool = x => tf.layers.maxPooling2d({poolSize: [2, 2]}).apply(x);
const up = x => tf.layers.upSampling2d({size: [2, 2]}).apply(x);
const cat = (a, b) => tf.layers.concatenate().apply([a, b]);
const inp = tf.input({shape: [Hp, Wp, 9]});
let x = conv('enc_conv1', conv('enc_conv0', inp)); const p1 = pool(x);
const p2 = pool(conv('enc_conv2', p1));
const p3 = pool(conv('enc_conv3', p2));
const p4 = pool(conv('enc_conv4', p3));
x = conv('enc_conv5b', conv('enc_conv5a', p4));
x = conv('dec_conv4b', conv('dec_conv4a', cat(up(x), p3)));
x = conv('dec_conv3b', conv('dec_conv3a', cat(up(x), p2)));
x = conv('dec_conv2b', conv('dec_conv2a', cat(up(x), p1)));
x = conv('dec_conv1b', conv('dec_conv1a', cat(up(x), inp)));
x = conv('dec_conv0', x);
const model = tf.model({inputs: inp, outputs: x});
const y = model.predict(tf.tensor(input, [1, Hp, Wp, 9])).dataSync();
const out = Buffer.alloc(12 + W * H * 3 * 4);
out.writeInt32LE(W, 0); out.writeInt32LE(H, 4); out.writeInt32LE(3, 8);
for (let yy = 0; yy < H; ++yy) for (let xx = 0; xx < W; ++xx) for (let c = 0; c < 3; ++c) {
  const v = clamp(nz(y[(yy * Wp + xx) * 3 + c]), 0, 3.4e38);
  out.writeFloatLE(puI(v / norm) / exposure, 12 + ((yy * W + xx) * 3 + c) * 4);
}
fs.writeFileSync(outPath, out);
console.log(`W ${W} H ${H} exposure ${exposure} backend ${tf.getBackend()}`);
