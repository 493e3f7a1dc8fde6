// Runs the Khronos glTF validator (npm package gltf-validator) on .glb/.gltf files and prints
// each report's counts and messages. Exit status: 0 when no file has an error (with --strict:
// no error and no warning), 1 otherwise, 2 for bad usage. Run through scripts/gltf-validate.sh,
// which installs the pinned validator and passes its folder:
//   node tests/gltf_validate.mjs --validator DIR [--strict] FILE...
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

function usage(message) {
  console.error(`gltf_validate: ${message}`);
  console.error('usage: node tests/gltf_validate.mjs --validator DIR [--strict] FILE...');
  process.exit(2);
}

const args = process.argv.slice(2);
let validatorDir = null;
let strict = false;
const files = [];
for (let i = 0; i < args.length; ++i) {
  if (args[i] === '--validator') validatorDir = args[++i];
  else if (args[i] === '--strict') strict = true;
  else if (args[i].startsWith('--')) usage(`unknown option ${args[i]}`);
  else files.push(args[i]);
}
if (!validatorDir) usage('--validator DIR is required');
if (files.length === 0) usage('no file given');

const validator = (await import(pathToFileURL(path.join(validatorDir, 'index.js')).href)).default;
const severityNames = ['error', 'warning', 'info', 'hint'];

let failed = false;
for (const file of files) {
  let report;
  try {
    const bytes = new Uint8Array(await readFile(file));
    // No external resources: a .glb carries everything; a reference outside it is an error.
    report = await validator.validateBytes(bytes, {
      uri: path.basename(file),
      maxIssues: 100,
      externalResourceFunction: (uri) => Promise.reject(new Error(`external resource ${uri}`)),
    });
  } catch (error) {
    console.error(`${file}: the validator could not run: ${error}`);
    failed = true;
    continue;
  }
  const issues = report.issues;
  console.log(
    `${file}: ${report.validatorVersion ? `glTF-Validator ${report.validatorVersion}` : 'glTF-Validator'}: ` +
      `numErrors ${issues.numErrors}, numWarnings ${issues.numWarnings}, ` +
      `numInfos ${issues.numInfos}, numHints ${issues.numHints}`);
  for (const m of issues.messages) {
    const where = m.pointer ?? (m.offset !== undefined ? `byte ${m.offset}` : '');
    console.log(`  ${severityNames[m.severity] ?? m.severity} ${m.code} ${where}: ${m.message}`);
  }
  if (issues.numErrors > 0 || (strict && issues.numWarnings > 0)) failed = true;
}
console.log(failed ? 'gltf_validate: FAILED' : 'gltf_validate: passed');
process.exit(failed ? 1 : 0);
