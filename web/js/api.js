// The studio's JSON API (docs/studio.md): requests and base64 GLB decoding.

/** An error the server reported: message plus file/line/column when the input was text. */
export class ApiError extends Error {
  constructor(error, status) {
    super(error?.message ?? `HTTP ${status}`);
    this.status = status;
    this.line = error?.line;
    this.column = error?.column;
  }
}

async function request(path, options) {
  const res = await fetch(path, options);
  let body;
  try {
    body = await res.json();
  } catch {
    throw new ApiError({ message: `HTTP ${res.status}: the server sent no JSON` }, res.status);
  }
  if (!res.ok) throw new ApiError(body.error, res.status);
  return body;
}

export const getExamples = () => request('/api/examples');

export const post = (path, body) =>
  request(path, {
    method: 'POST',
    headers: { 'Content-Type': 'application/json' },
    body: JSON.stringify(body),
  });

/** base64 → ArrayBuffer (the GLB inside API responses). */
export function decodeBase64(text) {
  const binary = atob(text);
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
  return bytes.buffer;
}

/** Offers `data` (Blob, ArrayBuffer or string) as a download named `name`. */
export function download(data, name, type = 'application/octet-stream') {
  const blob = data instanceof Blob ? data : new Blob([data], { type });
  const url = URL.createObjectURL(blob);
  const a = document.createElement('a');
  a.href = url;
  a.download = name;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}
