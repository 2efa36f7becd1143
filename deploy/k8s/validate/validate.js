// Validates every object of a rendered manifest stream (stdin) against the Kubernetes API
// schemas of the kubernetes-models package. Exits 1 naming each object that fails.
"use strict";
const fs = require("fs");
const yaml = require("js-yaml");

const GROUPS = {
  "v1": "kubernetes-models/v1",
  "apps/v1": "kubernetes-models/apps/v1",
  "policy/v1": "kubernetes-models/policy/v1",
  "networking.k8s.io/v1": "kubernetes-models/networking.k8s.io/v1",
};

const docs = yaml.loadAll(fs.readFileSync(0, "utf8")).filter(Boolean);
let failures = 0;
for (const doc of docs) {
  const name = `${doc.kind}/${doc.metadata && doc.metadata.name}`;
  const module = GROUPS[doc.apiVersion];
  if (!module) {
    console.error(`${name}: apiVersion ${doc.apiVersion} has no schema here`);
    failures++;
    continue;
  }
  const Model = require(module)[doc.kind];
  if (!Model) {
    console.error(`${name}: kind ${doc.kind} unknown in ${doc.apiVersion}`);
    failures++;
    continue;
  }
  try {
    new Model(doc).validate();
    console.log(`ok  ${name}`);
  } catch (e) {
    console.error(`bad ${name}: ${e.message}`);
    failures++;
  }
}
console.log(`${docs.length - failures} valid, ${failures} invalid`);
process.exit(failures === 0 && docs.length > 0 ? 0 : 1);
