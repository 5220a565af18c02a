// Runs the Khronos glTF validator (npm gltf-validator) on one .gltf or .glb file and prints
// {"errors": N, "warnings": N, "messages": [...]} as JSON. Exit code 2 when it cannot run.
const fs = require('fs');
const path = require('path');
const validator = require('gltf-validator');

const file = process.argv[2];
const bytes = new Uint8Array(fs.readFileSync(file));
const readResource = (uri) =>
  new Promise((resolve, reject) => {
    try {
      resolve(new Uint8Array(fs.readFileSync(path.join(path.dirname(file), decodeURIComponent(uri)))));
    } catch (error) {
      reject(error.toString());
    }
  });
validator
  .validateBytes(bytes, {uri: path.basename(file), externalResourceFunction: readResource, maxIssues: 50})
  .then((report) => {
    const messages = report.issues.messages.map((m) => `${m.severity} ${m.code} ${m.pointer || ''}: ${m.message}`);
    console.log(JSON.stringify({errors: report.issues.numErrors, warnings: report.issues.numWarnings, messages}));
  })
  .catch((error) => {
    console.error(String(error));
    process.exit(2);
  });
