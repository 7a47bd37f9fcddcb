#![allow(clippy::unwrap_used, clippy::expect_used)]
//! The asset store in an S3-compatible bucket, against a real S3-protocol server (moto,
//! installed by `scripts/setup.sh --tests`), and the asset library over it: the same
//! interface and guarantees as the local store, and two libraries on one bucket (two
//! workers) see each other's assets. Fails, never skips.

use std::sync::Arc;

use sw_forge::embed::MiniLm;
use sw_forge::library::{AssetLibrary, Sync};
use sw_forge::store::{AssetId, AssetRecord, AssetStore, StoreError};
use sw_forge::store_s3::S3Store;
use sw_s3::moto::MotoServer;

fn record(label: &str, size_m: [f64; 3]) -> AssetRecord {
    AssetRecord {
        id: AssetId::of(b""),
        label: label.into(),
        description: format!("a {label}"),
        source: "test".into(),
        size_m,
        triangles: 12,
        code: Some("result = cq.Workplane().box(1, 1, 1)".into()),
        extra: serde_json::json!({ "mass_kg": 2.5 }),
    }
}

#[test]
fn assets_round_trip_through_a_bucket_with_their_guarantees() {
    let server = MotoServer::start().unwrap();
    let store = S3Store::open(server.config("assets-test"), "forge/assets").unwrap();
    assert_eq!(store.location(), format!("s3://assets-test/forge/assets/ at http://{}", server.addr()));
    let mesh: Vec<u8> = (0..300_000u32).map(|i| (i * 13 % 251) as u8).collect();
    let a = store.put(&mesh, record("shelving unit", [1.0, 0.5, 2.0])).unwrap();
    assert_eq!(a.id, AssetId::of(&mesh));
    let b = store.put(b"cone", record("traffic cone", [0.3, 0.3, 0.5])).unwrap();
    // Putting the same mesh again relabels it and keeps one object.
    store.put(&mesh, record("storage rack", [1.0, 0.5, 2.0])).unwrap();
    assert_eq!(store.list().unwrap(), {
        let mut v = vec![a.id.clone(), b.id.clone()];
        v.sort();
        v
    });
    let back = store.record(&a.id).unwrap();
    assert_eq!(back.label, "storage rack");
    assert_eq!(back.extra["mass_kg"], 2.5);
    assert_eq!(store.mesh(&a.id).unwrap(), mesh);
    assert_eq!(store.resolve(&b.id.as_str()[..10]).unwrap(), b.id);
    assert!(matches!(store.record(&AssetId::of(b"nothing")), Err(StoreError::NotFound(_))));
    assert!(matches!(store.mesh(&AssetId::of(b"nothing")), Err(StoreError::NotFound(_))));
    // A tampered object is refused, not served.
    let raw = sw_s3::S3Client::new(server.config("assets-test"));
    let key = format!("forge/assets/objects/{}/{}.stl", &b.id.as_str()[..2], b.id);
    raw.put(&key, b"tampered").unwrap();
    assert!(matches!(store.mesh(&b.id), Err(StoreError::Corrupt { .. })));
    // Another prefix of the same bucket is another store.
    let other = S3Store::open(server.config("assets-test"), "elsewhere").unwrap();
    assert!(other.list().unwrap().is_empty());
    // Bad locations are refused with a clear error, before any request.
    assert!(matches!(S3Store::open(server.config("assets-test"), "a/../b"), Err(StoreError::BadLocation(_))));
    assert!(matches!(S3Store::open_url("s3:///x"), Err(StoreError::BadLocation(_))));
}

#[test]
fn an_unreachable_bucket_is_a_clear_error() {
    let server = MotoServer::start().unwrap();
    let mut config = server.config("gone");
    drop(server);
    config.endpoint = "http://127.0.0.1:9".into();
    let e = S3Store::open(config, "").unwrap_err();
    assert!(matches!(e, StoreError::Io { .. }), "{e}");
    assert!(e.to_string().contains("s3://gone/"), "{e}");
}

#[test]
fn two_libraries_on_one_bucket_reuse_each_others_assets() {
    let server = MotoServer::start().unwrap();
    let open = |index: &std::path::Path| {
        let store: Arc<dyn AssetStore> = Arc::new(S3Store::open(server.config("shared"), "assets").unwrap());
        AssetLibrary::open_with(store, index, MiniLm::load_default().unwrap()).unwrap()
    };
    let (ia, ib) = (tempfile::tempdir().unwrap(), tempfile::tempdir().unwrap());
    let a = open(ia.path());
    let rack = a.add(b"rack", record("shelving unit", [1.0, 0.5, 2.0])).unwrap();
    // Worker B starts after A stored the rack: its index picks it up from the bucket.
    let b = open(ib.path());
    assert_eq!(b.opened_with(), Sync { added: 1, dropped: 0, rebuilt: false });
    let found = b.lookup("storage rack", Some([0.95, 0.5, 1.9])).unwrap().expect("reused across workers");
    assert_eq!(found.record.id, rack.id);
    assert_eq!(b.store().mesh(&found.record.id).unwrap(), b"rack");
    // B stores a cone; A sees it after a sync, without reopening.
    b.add(b"cone", record("traffic cone", [0.3, 0.3, 0.5])).unwrap();
    assert!(a.lookup("road cone", None).unwrap().is_none());
    assert_eq!(a.sync().unwrap().added, 1);
    assert!(a.lookup("road cone", None).unwrap().is_some());
}
