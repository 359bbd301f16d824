// SPDX-License-Identifier: MIT
// Checks HJIF files against the repository's JSON Schema with Ajv, a validator of the JSON
// Schema standard (draft-07): node hjif-schema.mjs SCHEMA [--invalid] FILE...
// Each file prints "FILE: valid" or "FILE: invalid: /pointer: message". Exit status 0 when
// every file is as expected: valid, or with --invalid, refused.
import Ajv from "ajv";
import { readFileSync } from "node:fs";

const [schemaPath, ...rest] = process.argv.slice(2);
const expectInvalid = rest[0] === "--invalid";
const files = expectInvalid ? rest.slice(1) : rest;
if (!schemaPath || files.length === 0) {
  console.error("usage: node hjif-schema.mjs SCHEMA [--invalid] FILE...");
  process.exit(2);
}
// Strict: a keyword the validator does not know is an error in the schema, not ignored; a
// "required" inside if/then names properties defined beside it.
const ajv = new Ajv({ strict: true, strictRequired: false });
const validate = ajv.compile(JSON.parse(readFileSync(schemaPath, "utf8")));
let unexpected = 0;
for (const file of files) {
  const valid = validate(JSON.parse(readFileSync(file, "utf8")));
  if (valid) {
    console.log(`${file}: valid`);
  } else {
    const e = validate.errors[0];
    console.log(`${file}: invalid: ${e.instancePath || "/"}: ${e.message}`);
  }
  if (valid === expectInvalid) unexpected += 1;
}
process.exit(unexpected === 0 ? 0 : 1);
