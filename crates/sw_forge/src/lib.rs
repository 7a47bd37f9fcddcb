//! L2, the asset forge: turns an object description into a validated mesh.
//!
//! - [`runner`]: a pool of warm, sandboxed Python workers that run generated CadQuery
//!   (or OpenSCAD) code and hand back an STL or a structured error;
//! - [`validate`]: is the mesh a closed solid of the requested size, volume and number
//!   of through-holes;
//! - [`failure`]: the taxonomy every failed attempt is filed under;
//! - [`synth`]: the offline synthesizer, a feature language for dimensioned parts read from
//!   English, written as CadQuery code;
//! - [`freeform`]: free-form objects offline (the catalog's, or compositions of parts);
//! - [`part`]: synthesize, run, validate and write one part offline;
//! - [`suite`]: CAD prompt suites, their references, alignment and contact sheets;
//! - [`collision`]: convex collision pieces of generated parts (V-HACD), and parts as assets;
//! - [`generate`]: the generation loop — a writer (LLM or template) writes, the runner
//!   runs, the validator checks, failures go back to the writer, K attempts then fallback;
//! - [`store`]: meshes and metadata by content address, in a local directory or
//!   ([`store_s3`]) an S3-compatible bucket; [`index`]: the semantic index over their
//!   labels; `embed` (feature `embed`, on by default): all-MiniLM-L6-v2 on candle;
//!   `library`: the store, its index and the embedder together, with the size check
//!   that decides whether a stored asset serves a request.

pub mod collision;
#[cfg(feature = "embed")]
pub mod embed;
pub mod failure;
pub mod freeform;
pub mod generate;
pub mod index;
#[cfg(feature = "embed")]
pub mod library;
pub mod mesh_io;
pub mod metrics;
pub mod part;
pub mod reuse;
pub mod runner;
pub mod store;
pub mod store_s3;
pub mod suite;
pub mod synth;
pub mod validate;
