// The files a test tool was given: every argument that is a file with one of `extensions`
// (lower-case, with the dot), or the matching files below an argument that is a directory, in
// sorted order. Arguments that cannot be read are reported and counted, so a tool can fail
// on them instead of passing on fewer files.
import fs from 'node:fs';
import path from 'node:path';

function collect(target, extensions, out) {
  const stat = fs.statSync(target);
  if (stat.isDirectory()) {
    for (const entry of fs.readdirSync(target).sort()) collect(path.join(target, entry), extensions, out);
  } else if (extensions.has(path.extname(target).toLowerCase())) {
    out.push({ file: target, bytes: stat.size });
  }
}

/** { files: [{file, bytes}], unreadable: number of arguments that could not be read }. */
export function collectFiles(args, extensions) {
  const files = [];
  let unreadable = 0;
  for (const arg of args) {
    try {
      collect(arg, extensions, files);
    } catch (err) {
      console.log(`${arg}: cannot read: ${err.message}`);
      ++unreadable;
    }
  }
  return { files, unreadable };
}
