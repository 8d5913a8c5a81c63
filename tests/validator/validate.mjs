// Validates glTF assets with the Khronos glTF validator (npm gltf-validator).
//
//   node tests/validator/validate.mjs DIR_OR_FILE...
//
// Every .glb/.gltf given is validated; directories are searched recursively (in sorted order).
// Prints "ok" or the validator's error messages per file, warning/info counts, and a final line
// "validated N files: P passed, F failed". Exits 1 when any file has errors, when a path cannot
// be read, or when no file was found at all (so an empty test-output directory cannot pass).
import fs from 'node:fs';
import path from 'node:path';
import process from 'node:process';
import validator from 'gltf-validator';
import { collectFiles } from '../common/collect_files.mjs';

const kExtensions = new Set(['.glb', '.gltf']);
const kSeverityNames = ['error', 'warning', 'info', 'hint'];

function loadExternal(file) {
    return (uri) => fs.promises.readFile(path.resolve(path.dirname(file),
                                                      decodeURIComponent(uri)));
}

async function validateFile(file) {
    const bytes = new Uint8Array(fs.readFileSync(file));
    const report = await validator.validateBytes(bytes, {
        uri: path.basename(file),
        maxIssues: 0,
        writeTimestamp: false,
        externalResourceFunction: loadExternal(file),
    });
    const issues = report.issues;
    const counts = `${issues.numWarnings} warnings, ${issues.numInfos} infos, ` +
                   `${issues.numHints} hints`;
    if (issues.numErrors === 0) {
        console.log(`${file}: ok (${counts})`);
        return true;
    }
    console.log(`${file}: ${issues.numErrors} errors (${counts})`);
    for (const m of issues.messages) {
        if (m.severity !== 0) continue;
        const where = m.pointer ? ` at ${m.pointer}` : '';
        console.log(`  ${kSeverityNames[m.severity]} ${m.code}${where}: ${m.message}`);
    }
    return false;
}

async function main(args) {
    if (args.length === 0) {
        console.error('usage: node validate.mjs DIR_OR_FILE...');
        return 2;
    }
    const collected = collectFiles(args, kExtensions);
    const files = collected.files.map((f) => f.file);
    const { unreadable } = collected;
    let passed = 0;
    let failed = 0;
    for (const file of files) {
        let ok = false;
        try {
            ok = await validateFile(file);
        } catch (err) {
            console.log(`${file}: validator could not read the asset: ${err}`);
        }
        if (ok) passed += 1;
        else failed += 1;
    }
    console.log(`validated ${files.length} files: ${passed} passed, ${failed} failed`);
    if (files.length === 0) {
        console.log('error: no .glb or .gltf files found');
        return 1;
    }
    return failed === 0 && unreadable === 0 ? 0 : 1;
}

process.exitCode = await main(process.argv.slice(2));
