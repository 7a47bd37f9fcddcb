//! The S3 blob store against a real S3-protocol server: moto's server mode, installed from
//! PyPI by `scripts/setup.sh --tests` and started on loopback (`sw_s3::moto`).

#![allow(clippy::unwrap_used, clippy::expect_used)]

use sw_s3::moto::MotoServer;
use sw_store::{BlobStore, S3Blobs};

fn blobs(server: &MotoServer, bucket: &str) -> S3Blobs {
    let b = S3Blobs::new(server.config(bucket));
    b.ensure_bucket().unwrap();
    b.ensure_bucket().unwrap();
    b
}

#[test]
fn packages_round_trip_through_an_s3_server() {
    let server = MotoServer::start().unwrap();
    let b = blobs(&server, "scenes-test");
    let xml = b"<mujoco model=\"scene\"/>".to_vec();
    let stl: Vec<u8> = (0..200_000u32).map(|i| (i * 7 % 251) as u8).collect();
    b.put("scenes/abc/scene.xml", &xml).unwrap();
    b.put("scenes/abc/assets/mesh 1+odd=name.stl", &stl).unwrap();
    b.put("scenes/abd/scene.xml", b"other").unwrap();
    assert_eq!(b.get("scenes/abc/scene.xml").unwrap().unwrap(), xml);
    assert_eq!(b.get("scenes/abc/assets/mesh 1+odd=name.stl").unwrap().unwrap(), stl);
    assert_eq!(b.get("scenes/abc/missing.xml").unwrap(), None);
    // Overwrite.
    b.put("scenes/abc/scene.xml", b"v2").unwrap();
    assert_eq!(b.get("scenes/abc/scene.xml").unwrap().unwrap(), b"v2");
    // Listing pages through more keys than one answer holds (moto pages at 1000).
    for i in 0..1005 {
        b.put(&format!("scenes/many/{i:04}.json"), b"{}").unwrap();
    }
    assert_eq!(b.list("scenes/many/").unwrap().len(), 1005);
    // Deleting a prefix removes that scene only (not `scenes/abd/`, which shares a prefix string).
    b.delete_prefix("scenes/abc/").unwrap();
    assert_eq!(b.get("scenes/abc/scene.xml").unwrap(), None);
    assert!(b.list("scenes/abc/").unwrap().is_empty());
    assert_eq!(b.get("scenes/abd/scene.xml").unwrap().unwrap(), b"other");
    b.delete_prefix("scenes/many").unwrap();
    assert!(b.list("scenes/many/").unwrap().is_empty());
    // Keys that escape are refused before any request.
    for k in ["../x", "/abs", "a//b", "a/../b"] {
        assert!(b.put(k, b"x").is_err(), "{k}");
        assert!(b.get(k).is_err(), "{k}");
    }
}

#[test]
fn a_missing_bucket_is_an_error_not_an_empty_answer() {
    let server = MotoServer::start().unwrap();
    let b = S3Blobs::new(server.config("never-created"));
    assert!(b.get("scenes/x/scene.xml").is_err());
    assert!(b.put("scenes/x/scene.xml", b"x").is_err());
}
