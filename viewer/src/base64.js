// The page's arrays travel as base64 text of little-endian binary (docs/viewer.md): far smaller
// and faster to read than JSON numbers for a cloud of 300,000 points.

function bytesOf(text) {
  const binary = atob(text);
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; i++) bytes[i] = binary.charCodeAt(i);
  return bytes;
}

/** Float32Array of the base64 text of little-endian 32-bit floats. */
export function decodeFloat32(text) {
  const bytes = bytesOf(text);
  return new Float32Array(bytes.buffer, 0, bytes.length / 4);
}


/** Int16Array of the base64 text of little-endian 16-bit integers. */
export function decodeInt16(text) {
  const bytes = bytesOf(text);
  return new Int16Array(bytes.buffer, 0, bytes.length / 2);
}

/** Uint32Array of the base64 text of little-endian 32-bit unsigned integers. */
export function decodeUint32(text) {
  const bytes = bytesOf(text);
  return new Uint32Array(bytes.buffer, 0, bytes.length / 4);
}
