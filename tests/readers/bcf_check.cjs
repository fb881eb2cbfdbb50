// SPDX-License-Identifier: GPL-3.0-or-later
// Opens a BCF archive in @parametricos/bcf-js (a BCF 2.1 reader from npm) and prints what it
// read as JSON: the version and each topic's GUID, title, status, labels, the IFC GlobalIds
// its viewpoints select and the bytes of their PNG snapshots; with an IFC file too, every IfcRoot GlobalId web-ifc reads from it.
// Exit status: 0 read, 1 the reader failed or logged an error, 2 usage.
// Usage: node tests/readers/bcf_check.cjs FILE.bcfzip [FILE.ifc]
'use strict';
const fs = require('fs');
const path = require('path');
const { BcfReader } = require(path.join(__dirname, 'node_modules', '@parametricos', 'bcf-js', 'dist', '2.1'));
const WebIFC = require(path.join(__dirname, 'node_modules', 'web-ifc'));

/// Every GlobalId of an IFC file, as web-ifc reads its lines.
async function globalIds(file) {
  const api = new WebIFC.IfcAPI();
  await api.Init();
  const model = api.OpenModel(new Uint8Array(fs.readFileSync(file)));
  if (model < 0) throw new Error(`web-ifc could not open ${file}`);
  const ids = [];
  const lines = api.GetAllLines(model);
  for (let i = 0; i < lines.size(); ++i) {
    const line = api.GetLine(model, lines.get(i));
    if (line && line.GlobalId && line.GlobalId.value) ids.push(line.GlobalId.value);
  }
  return ids;
}

async function main() {
  if (process.argv.length < 3 || process.argv.length > 4) {
    console.error('usage: node bcf_check.cjs FILE.bcfzip [FILE.ifc]');
    process.exit(2);
  }
  const errors = [];
  const logError = console.error;
  console.error = (...a) => errors.push(a.join(' '));
  console.log = (...a) => errors.push(a.join(' '));
  const reader = new BcfReader();
  await reader.read(new Uint8Array(fs.readFileSync(process.argv[2])));
  const project = reader.project;
  const out = { version: project ? project.version : null, topics: [], messages: errors };
  for (const markup of reader.markups) {
    const t = markup.topic;
    const components = [];
    let snapshot = 0;  // the bytes of the viewpoints' PNG snapshots, as the reader returns them
    for (const v of markup.viewpoints) {
      const selection = v.components && v.components.selection;
      for (const c of selection || []) components.push(c.ifc_guid);
      const png = await v.getSnapshot();
      if (png) snapshot += Buffer.from(png, 'base64').subarray(0, 8).equals(
        Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a])) ? Buffer.from(png, 'base64').length : 0;
    }
    out.topics.push({ guid: t.guid, title: t.title, status: t.topic_status, type: t.topic_type,
      labels: t.labels || [], components, snapshot,
      camera: markup.viewpoints.some((v) => !!v.perspective_camera) });
  }
  if (process.argv[3]) out.ifc_global_ids = await globalIds(process.argv[3]);
  process.stdout.write(JSON.stringify(out) + '\n');
  console.error = logError;
  process.exit(project && errors.length === 0 ? 0 : 1);
}

main().catch((e) => { process.stderr.write(String(e && e.stack || e) + '\n'); process.exit(1); });
