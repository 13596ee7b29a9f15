// Where the page's files come from: the `mechsim view` server (report files under report/, the
// server's verdict on the folder in status.json) or, in a page written by `mechsim view --export`,
// the base64 copies embedded in the page itself (window.MECHSIM_EMBED), so that it works offline.

const embedded = () => (typeof window !== 'undefined' ? window.MECHSIM_EMBED : undefined);

function decodeBase64(text) {
  const binary = atob(text);
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; i++) bytes[i] = binary.charCodeAt(i);
  return bytes;
}

// `path` is relative to the report folder ("replay/manifest.json").
export async function readBytes(path) {
  const embed = embedded();
  if (embed) {
    const text = embed.files[path];
    if (text === undefined) throw new Error(`the exported page holds no ${path}`);
    return decodeBase64(text);
  }
  const response = await fetch(`report/${path}`);
  if (!response.ok) throw new Error(`${path}: HTTP ${response.status}`);
  return new Uint8Array(await response.arrayBuffer());
}

export async function readText(path) {
  return new TextDecoder().decode(await readBytes(path));
}

export async function readJson(path) {
  const text = await readText(path);
  try {
    return JSON.parse(text);
  } catch (e) {
    throw new Error(`${path}: not JSON (${e.message})`);
  }
}

// The server's (or the export's) check of the report folder: {ok, error, report}.
export async function readStatus() {
  const embed = embedded();
  if (embed) return embed.status;
  const response = await fetch('status.json');
  if (!response.ok) throw new Error(`status.json: HTTP ${response.status}`);
  return response.json();
}

// A URL an <img> can show: the server's path, or a data: URL in an exported page.
export function imageUrl(path) {
  const embed = embedded();
  if (embed) return `data:image/png;base64,${embed.files[path] ?? ''}`;
  return `report/${path}`;
}

// Normalises "replay/../x.png" to "x.png" (the manifest names plots relative to replay/).
export function reportPath(relativeToReplay) {
  const parts = [];
  for (const part of `replay/${relativeToReplay}`.split('/')) {
    if (part === '..') parts.pop();
    else if (part !== '.' && part !== '') parts.push(part);
  }
  return parts.join('/');
}
