//! The OpenAPI 3.1 document served at `/api/openapi.json`, written by hand next to the
//! routes (a test checks that every route is in it).

use axum::Json;
use serde_json::{Value, json};

fn op(summary: &str, auth: bool, body: Option<Value>, ok: (&str, &str), errors: &[&str]) -> Value {
    let mut responses = serde_json::Map::new();
    responses.insert(ok.0.to_string(), json!({ "description": ok.1 }));
    for e in errors {
        responses.insert((*e).to_string(), json!({ "$ref": format!("#/components/responses/E{e}") }));
    }
    let mut v = json!({ "summary": summary, "responses": responses });
    if auth {
        v["security"] = json!([{ "bearer": [] }, { "apiKey": [] }]);
    }
    if let Some(schema) = body {
        v["requestBody"] = json!({ "required": true, "content": { "application/json": { "schema": schema } } });
    }
    v
}

fn id_param(name: &str) -> Value {
    json!({ "name": name, "in": "path", "required": true, "schema": { "type": "string", "pattern": "^[0-9a-f]{32}$" } })
}

/// The document.
pub fn spec() -> Value {
    let creds = json!({ "type": "object", "required": ["username", "password"], "additionalProperties": false,
        "properties": { "username": { "type": "string", "minLength": 3, "maxLength": 64, "pattern": "^[A-Za-z0-9_.-]+$" },
                        "password": { "type": "string", "minLength": 8, "maxLength": 1024 } } });
    let job_req = json!({ "type": "object", "required": ["prompt"], "additionalProperties": false, "properties": {
        "prompt": { "type": "string", "maxLength": crate::PROMPT_LIMIT, "description": "what the scene holds, in English (at most 64 KiB)" },
        "seed": { "type": "integer", "minimum": 0 },
        "variations": { "type": "integer", "minimum": 1, "maximum": crate::MAX_VARIATIONS, "description": "scenes to make, one per seed from `seed` up; queued together or not at all" },
        "robots": { "type": "array", "maxItems": sw_plan::MAX_ROBOTS, "items": { "type": "string" }, "description": "registry robots instead of the prompt's (at most 16; \"none\" entries not counted)" },
        "options": { "type": "object", "additionalProperties": false, "properties": {
            "verify": { "type": "boolean", "default": true }, "rules": { "type": "string" },
            "anomaly": { "type": "object", "required": ["kinds", "rate"], "properties": {
                "kinds": { "type": "array", "minItems": 1, "items": { "enum": ["overlap", "scale", "misplacement", "floating", "rule_violation"] } },
                "rate": { "type": "number", "exclusiveMinimum": 0, "maximum": 1 } } } } } } });
    let jobs_auth = ["400", "401", "404", "422"];
    let mut doc = json!({
        "openapi": "3.1.0",
        "info": { "title": "scenewright", "version": env!("CARGO_PKG_VERSION"),
                  "description": "Plain-English descriptions in, verified MuJoCo scenes out. Another user's job, scene or asset answers 404 exactly as a missing one." },
        "paths": {
            "/healthz": { "get": op("Health: 200 when the database answers and the database and package store can write; 503 (with Retry-After) naming which cannot", false, None, ("200", "ok"), &["503"]) },
            "/metrics": { "get": op("Prometheus metrics (admins; a scraper uses an admin's API key)", true, None, ("200", "text exposition format"), &["401", "403"]) },
            "/api/openapi.json": { "get": op("This document", false, None, ("200", "OpenAPI 3.1"), &[]) },
            "/api/auth/register": { "post": op("Create a user (the first is the admin)", false, Some(creds.clone()), ("201", "the user"), &["400", "409", "415", "422"]) },
            "/api/auth/login": { "post": op("Log in (names in any case): an access token (JWT, HS256); 429 with Retry-After after repeated wrong passwords", false, Some(creds), ("200", "{token, token_type, expires_in, username}"), &["400", "401", "422", "429"]) },
            "/api/auth/logout": { "post": op("Revoke the access token of this request (signing out)", true, None, ("204", "revoked"), &["401", "422"]) },
            "/api/auth/keys/{id}": { "parameters": [id_param("id")],
                "delete": op("Revoke one of the caller's API keys: it stops working at once", true, None, ("204", "revoked"), &["401", "404"]) },
            "/api/auth/keys": { "post": op("Create an API key for scripts (shown once)", true,
                Some(json!({ "type": "object", "required": ["name"], "properties": { "name": { "type": "string" } } })), ("201", "{id, name, key}"), &["401", "422"]) },
            "/api/me": { "get": op("The caller", true, None, ("200", "the user"), &["401"]) },
            "/api/jobs": {
                "post": op("Queue a scene generation (or `variations` of it); everything that scales the work is checked first (422 says which bound); 429 with Retry-After when the queue or the caller's share of it is full", true, Some(job_req), ("202", "{job_id, job_ids, state}"), &["400", "401", "413", "415", "422", "429", "503"]),
                "get": op("The caller's jobs, newest first (?limit=1..200)", true, None, ("200", "{jobs}"), &["401", "422"]) },
            "/api/jobs/{id}": {
                "parameters": [id_param("id")],
                "get": op("A job: state, stage, attempts, queue wait, error, scene_id", true, None, ("200", "the job"), &jobs_auth),
                "delete": op("Cancel a job (a queued job never runs; a running job's result is discarded)", true, None, ("200", "the job"), &jobs_auth) },
            "/api/jobs/{id}/events": {
                "parameters": [id_param("id")],
                "get": op("WebSocket: one JSON message per event (queued, started, stage_started, stage_finished, object, note, warning, requeued, error, cancelled, finished), then `result`; token in the header or ?token= (the only route that takes one in the URL)", true, None, ("101", "switching protocols"), &jobs_auth) },
            "/api/scenes": { "get": op("The caller's scenes", true, None, ("200", "{scenes}"), &["401"]) },
            "/api/scenes/{id}": { "parameters": [id_param("id")],
                "get": op("A scene: metadata, report.json, files, edit history", true, None, ("200", "the scene"), &jobs_auth),
                "delete": op("Delete the scene with every version of its lineage, and their files", true, None, ("200", "{deleted}"), &jobs_auth) },
            "/api/scenes/{id}/files/{path}": { "parameters": [id_param("id"), { "name": "path", "in": "path", "required": true, "schema": { "type": "string" } }],
                "get": op("One file of the package (scene.xml, assets/…)", true, None, ("200", "the file"), &jobs_auth) },
            "/api/scenes/{id}/package.zip": { "parameters": [id_param("id")],
                "get": op("The package as a zip", true, None, ("200", "application/zip"), &jobs_auth) },
            "/api/scenes/{id}/edits": { "parameters": [id_param("id")],
                "post": op("Queue a plain-English edit; the job makes the next version", true,
                    Some(json!({ "type": "object", "required": ["command"], "properties": { "command": { "type": "string", "maxLength": crate::PROMPT_LIMIT } } })),
                    ("202", "{job_id, state, scene_id}"), &["400", "401", "404", "413", "422", "429"]) },
            "/api/assets": {
                "get": op("Catalog categories and the caller's assets matching ?q=", true, None, ("200", "{catalog, mine}"), &["400", "401"]),
                "post": op("An asset for a description: a catalog category, or from the asset forge (reused from the library by meaning and size, else generated, validated and stored); 422 when it cannot be made", true,
                    Some(json!({ "type": "object", "required": ["description"], "properties": {
                        "description": { "type": "string", "maxLength": 4096 },
                        "size_m": { "type": "array", "items": { "type": "number", "minimum": 0.0005, "maximum": 50 }, "minItems": 3, "maxItems": 3, "description": "bounding box, metres: width, depth, height" } } })),
                    ("201", "the asset; meta.source is catalog, library or generated"), &["400", "401", "413", "422", "503"]) },
            "/api/assets/{id}": { "parameters": [id_param("id")],
                "get": op("One of the caller's assets", true, None, ("200", "the asset"), &["401", "404"]) },
            "/api/assets/{id}/mesh.stl": { "parameters": [id_param("id")],
                "get": op("The mesh of a generated or reused asset (binary STL, metres)", true, None, ("200", "model/stl"), &["401", "404", "503"]) },
            "/api/robots": { "get": op("The robot registry", true, None, ("200", "{robots}"), &["401"]) },
            "/api/admin/jobs": { "get": op("Jobs by state (admins)", true, None, ("200", "{by_state}"), &["401", "403"]) },
        },
        "components": {
            "securitySchemes": {
                "bearer": { "type": "http", "scheme": "bearer", "bearerFormat": "JWT or API key (swk_…)" },
                "apiKey": { "type": "apiKey", "in": "header", "name": "X-API-Key" } },
            "schemas": { "Error": { "type": "object", "required": ["error"], "properties": { "error": { "type": "string" } } } },
            "responses": Value::Object(["400", "401", "403", "404", "409", "413", "415", "422", "429", "500", "503"].iter().map(|c| {
                (format!("E{c}"), json!({ "description": c, "content": { "application/json": { "schema": { "$ref": "#/components/schemas/Error" } } } }))
            }).collect()),
        },
    });
    app_paths(&mut doc);
    doc
}

/// The routes the browser app added: refinement, options, key listing, versions,
/// thumbnails, structured edits, search by meaning and the forge's progress stream.
fn app_paths(doc: &mut Value) {
    let auth = ["401", "404"];
    let pos = json!({ "type": "array", "items": { "type": "number" }, "minItems": 2, "maxItems": 2, "description": "x, y in the room, metres" });
    let edit = json!({ "oneOf": [
        { "type": "object", "required": ["command"], "properties": { "command": { "type": "string", "maxLength": crate::PROMPT_LIMIT } } },
        { "type": "object", "required": ["move"], "properties": { "move": { "type": "object", "required": ["object", "pos"], "properties": {
            "object": { "type": "string" }, "pos": pos, "yaw_deg": { "type": "number" } } } } },
        { "type": "object", "required": ["place"], "properties": { "place": { "type": "object", "required": ["asset", "pos"], "properties": {
            "asset": { "type": "string", "description": "catalog:<category> or one of the caller's asset ids" }, "pos": pos, "yaw_deg": { "type": "number" } } } } } ] });
    let refine = json!({ "type": "object", "properties": { "prompt": { "type": "string" }, "turns": { "type": "array", "items": {
        "type": "object", "required": ["question", "answer"], "properties": { "question": { "type": "string" }, "answer": { "type": "string" } } } } } });
    let paths = &mut doc["paths"];
    paths["/api/auth/keys"]["get"] =
        op("The caller's API keys (id, name, created; never the key)", true, None, ("200", "{keys}"), &["401"]);
    paths["/api/options"] = json!({ "get": op("What a job may ask for: rules profiles, anomaly kinds", true, None, ("200", "{rules_profiles, anomaly_kinds}"), &["401"]) });
    paths["/api/refine"] = json!({ "post": op("One turn of the refinement chat (send the transcript so far): the next question, or the final prompt", true, Some(refine),
        ("200", "{done, question, prompt, asked_by, turns, summary?, warnings}"), &["400", "401", "413", "422"]) });
    paths["/api/scenes/{id}/edits"]["post"] = op(
        "Queue an edit: a sentence, an object moved or turned to a pose, or a library part placed at a point; the job re-solves around it, keeps it in the room, re-verifies and makes the next version or fails with the reason",
        true,
        Some(edit),
        ("202", "{job_id, state, scene_id}"),
        &["400", "401", "404", "413", "422", "429"],
    );
    paths["/api/scenes/{id}/versions"] = json!({ "parameters": [id_param("id")],
        "get": op("Every version of the scene's lineage, oldest first, with the edit that made each", true, None, ("200", "{scene_id, versions}"), &auth) });
    paths["/api/scenes/{id}/thumbnail.png"] = json!({ "parameters": [id_param("id")],
        "get": op("A 480 × 300 picture of the scene (drawn once, then kept)", true, None, ("200", "image/png"), &auth) });
    paths["/api/catalog/{name}/picture.png"] = json!({ "parameters": [{ "name": "name", "in": "path", "required": true, "schema": { "type": "string" } }],
        "get": op("A 256 × 256 picture of a catalog category, built at seed 0 (public; drawn once per process)", false, None, ("200", "image/png"), &["404"]) });
    paths["/api/assets"]["get"] = op(
        "Catalog categories and the caller's assets matching ?q= by words, and (similar) the caller's generated parts nearest in meaning, with scores",
        true,
        None,
        ("200", "{catalog, mine, similar, note}"),
        &["400", "401"],
    );
    paths["/api/assets"]["post"]["parameters"] = json!([{ "name": "stream", "in": "query", "required": false, "schema": { "enum": [1] },
        "description": "1: answer application/x-ndjson — progress and each failed attempt with its failure kind, then the asset or the error" }]);
}

pub async fn document() -> Json<Value> {
    Json(spec())
}
