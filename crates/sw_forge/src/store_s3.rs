//! The asset store in an S3-compatible bucket (AWS S3, MinIO, moto, …): the same content
//! addresses as [`LocalStore`](crate::store::LocalStore), as keys
//! `<prefix>objects/<first two hex>/<hash>.stl` and `.json`. The mesh is written before
//! its record, so a record that lists is always servable; a PUT replaces an object
//! atomically, so a reader never sees half of one.

pub use sw_s3::S3Config;
use sw_s3::{S3Client, S3Error};

use crate::store::{AssetId, AssetRecord, AssetStore, StoreError};

/// Assets in a bucket under a key prefix.
#[derive(Debug, Clone)]
pub struct S3Store {
    client: S3Client,
    prefix: String,
}

fn s3(e: S3Error) -> StoreError {
    let path = match &e {
        S3Error::Transport { target, .. } | S3Error::Status { target, .. } | S3Error::Answer { target, .. } => {
            target.clone()
        }
    };
    StoreError::Io { path, message: e.to_string() }
}

impl S3Store {
    /// A store under `prefix` (`""` or `assets/`; a missing trailing `/` is added) of the
    /// configured bucket, which is created if it does not exist.
    pub fn open(config: S3Config, prefix: &str) -> Result<Self, StoreError> {
        let prefix = prefix.trim_matches('/');
        let prefix = if prefix.is_empty() { String::new() } else { format!("{prefix}/") };
        if prefix.split('/').any(|s| s == "." || s == "..") || prefix.contains("//") {
            return Err(StoreError::BadLocation(format!("s3://{}/{prefix}", config.bucket)));
        }
        let client = S3Client::new(config);
        client.ensure_bucket().map_err(s3)?;
        Ok(Self { client, prefix })
    }

    /// Opens `s3://bucket/prefix` on the endpoint and with the credentials of the
    /// environment ([`S3Config::from_env`]).
    pub fn open_url(url: &str) -> Result<Self, StoreError> {
        let rest = url.strip_prefix("s3://").ok_or_else(|| StoreError::BadLocation(url.to_string()))?;
        let (bucket, prefix) = rest.split_once('/').unwrap_or((rest, ""));
        if bucket.is_empty() {
            return Err(StoreError::BadLocation(url.to_string()));
        }
        let config = S3Config::from_env().ok_or_else(|| StoreError::Io {
            path: url.to_string(),
            message:
                "an s3:// asset store needs SCENEWRIGHT_S3_ENDPOINT (and AWS_ACCESS_KEY_ID, AWS_SECRET_ACCESS_KEY)"
                    .into(),
        })?;
        Self::open(config.with_bucket(bucket), prefix)
    }

    fn key(&self, id: &AssetId, ext: &str) -> String {
        format!("{}objects/{}/{}.{ext}", self.prefix, &id.as_str()[..2], id.as_str())
    }
}

impl AssetStore for S3Store {
    fn put(&self, stl: &[u8], mut record: AssetRecord) -> Result<AssetRecord, StoreError> {
        let id = AssetId::of(stl);
        record.id = id.clone();
        let mesh = self.key(&id, "stl");
        if !self.client.exists(&mesh).map_err(s3)? {
            self.client.put(&mesh, stl).map_err(s3)?;
        }
        let json = serde_json::to_vec_pretty(&record)
            .map_err(|e| StoreError::Io { path: self.key(&id, "json"), message: e.to_string() })?;
        self.client.put(&self.key(&id, "json"), &json).map_err(s3)?;
        Ok(record)
    }

    fn record(&self, id: &AssetId) -> Result<AssetRecord, StoreError> {
        let key = self.key(id, "json");
        let bytes = self.client.get(&key).map_err(s3)?.ok_or_else(|| StoreError::NotFound(id.to_string()))?;
        serde_json::from_slice(&bytes).map_err(|e| StoreError::Io { path: key, message: e.to_string() })
    }

    fn mesh(&self, id: &AssetId) -> Result<Vec<u8>, StoreError> {
        let key = self.key(id, "stl");
        let bytes = self.client.get(&key).map_err(s3)?.ok_or_else(|| StoreError::NotFound(id.to_string()))?;
        if AssetId::of(&bytes) != *id {
            return Err(StoreError::Corrupt { path: key });
        }
        Ok(bytes)
    }

    fn list(&self) -> Result<Vec<AssetId>, StoreError> {
        let objects = format!("{}objects/", self.prefix);
        let mut ids: Vec<AssetId> = self
            .client
            .list(&objects)
            .map_err(s3)?
            .iter()
            .filter_map(|k| k.strip_prefix(&objects)?.split_once('/')?.1.strip_suffix(".json"))
            .filter_map(|s| AssetId::parse(s).ok())
            .collect();
        ids.sort();
        Ok(ids)
    }

    fn location(&self) -> String {
        let c = self.client.config();
        format!("s3://{}/{} at {}", c.bucket, self.prefix, c.endpoint)
    }
}
