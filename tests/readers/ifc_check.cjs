// SPDX-License-Identifier: GPL-3.0-or-later
// Opens an IFC file in web-ifc (ThatOpen's IFC reader, npm `web-ifc`) and prints what it read as
// JSON: the schema, element counts by type, and each product's mesh volume (web-ifc meshes it,
// cutting openings from their walls; float32 vertices) with its GlobalId, type and Name.
// Exit status: 0 read, 1 web-ifc refused the file or logged an error, 2 usage.
// Usage: node tests/readers/ifc_check.cjs FILE.ifc
'use strict';
const fs = require('fs');
const path = require('path');
const WebIFC = require(path.join(__dirname, 'node_modules', 'web-ifc'));

const kTypes = ['IFCPROJECT', 'IFCSITE', 'IFCBUILDING', 'IFCBUILDINGSTOREY', 'IFCWALL',
  'IFCWALLSTANDARDCASE', 'IFCOPENINGELEMENT', 'IFCDOOR', 'IFCWINDOW', 'IFCSLAB', 'IFCSPACE',
  'IFCRELVOIDSELEMENT', 'IFCRELFILLSELEMENT', 'IFCRELCONTAINEDINSPATIALSTRUCTURE',
  'IFCRELAGGREGATES', 'IFCSURFACESTYLE'];

/// The signed volume of a triangle mesh placed by a 4x4 column-major matrix.
function volume(vertices, indices, m) {
  const at = (k) => {
    const x = vertices[6 * k], y = vertices[6 * k + 1], z = vertices[6 * k + 2];
    return [m[0] * x + m[4] * y + m[8] * z + m[12], m[1] * x + m[5] * y + m[9] * z + m[13],
      m[2] * x + m[6] * y + m[10] * z + m[14]];
  };
  let v = 0;
  for (let t = 0; t + 2 < indices.length; t += 3) {
    const a = at(indices[t]), b = at(indices[t + 1]), c = at(indices[t + 2]);
    v += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
      a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
  }
  return v;
}

async function main() {
  if (process.argv.length !== 3) {
    console.error('usage: node ifc_check.cjs FILE.ifc');
    process.exit(2);
  }
  const api = new WebIFC.IfcAPI();
  await api.Init();
  const messages = [];
  for (const k of ['log', 'warn', 'error']) console[k] = (...a) => messages.push(`${k}: ${a.join(' ')}`);
  api.SetLogLevel(WebIFC.LogLevel.LOG_LEVEL_WARN);
  const model = api.OpenModel(new Uint8Array(fs.readFileSync(process.argv[2])));
  const out = { opened: model >= 0, schema: null, counts: {}, products: [], messages };
  if (model >= 0) {
    out.schema = api.GetModelSchema(model);
    for (const name of kTypes) out.counts[name] = api.GetLineIDsWithType(model, WebIFC[name]).size();
    api.StreamAllMeshes(model, (mesh) => {
      const line = api.GetLine(model, mesh.expressID);
      let v = 0;
      for (let i = 0; i < mesh.geometries.size(); ++i) {
        const placed = mesh.geometries.get(i);
        const g = api.GetGeometry(model, placed.geometryExpressID);
        v += volume(api.GetVertexArray(g.GetVertexData(), g.GetVertexDataSize()),
          api.GetIndexArray(g.GetIndexData(), g.GetIndexDataSize()), placed.flatTransformation);
        g.delete();
      }
      out.products.push({ id: mesh.expressID, global_id: line.GlobalId ? line.GlobalId.value : null,
        type: api.GetNameFromTypeCode(line.type).toUpperCase(), name: line.Name ? line.Name.value : null, volume: v });
    });
    api.CloseModel(model);
  }
  process.stdout.write(JSON.stringify(out) + '\n');
  process.exit(out.opened && !messages.some((m) => m.startsWith('error')) ? 0 : 1);
}
main().catch((e) => { process.stderr.write(`ifc_check: ${e.stack || e}\n`); process.exit(1); });
