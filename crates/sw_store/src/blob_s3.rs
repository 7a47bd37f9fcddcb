//! Package blobs in an S3-compatible bucket, through `sw_s3`'s signed client. Keys are
//! checked like the local store's before any request.

use crate::blob::{BlobError, BlobStore, check_key};
use sw_s3::{S3Client, S3Config, S3Error};

/// A bucket as a blob store.
#[derive(Debug, Clone)]
pub struct S3Blobs {
    client: S3Client,
}

fn io(e: S3Error) -> BlobError {
    BlobError::Io(std::io::Error::other(e.to_string()))
}

impl S3Blobs {
    pub fn new(config: S3Config) -> Self {
        Self { client: S3Client::new(config) }
    }

    /// Creates the bucket if it does not exist.
    pub fn ensure_bucket(&self) -> Result<(), BlobError> {
        self.client.ensure_bucket().map_err(io)
    }

    /// Keys under a prefix.
    pub fn list(&self, prefix: &str) -> Result<Vec<String>, BlobError> {
        self.client.list(prefix).map_err(io)
    }
}

impl BlobStore for S3Blobs {
    fn put(&self, key: &str, data: &[u8]) -> Result<(), BlobError> {
        check_key(key)?;
        self.client.put(key, data).map_err(io)
    }

    fn get(&self, key: &str) -> Result<Option<Vec<u8>>, BlobError> {
        check_key(key)?;
        self.client.get(key).map_err(io)
    }

    fn delete_prefix(&self, prefix: &str) -> Result<(), BlobError> {
        check_key(prefix)?;
        // `scenes/abc/` must not take `scenes/abcd/` with it.
        let prefix = format!("{}/", prefix.trim_end_matches('/'));
        for key in self.client.list(&prefix).map_err(io)? {
            self.client.delete(&key).map_err(io)?;
        }
        Ok(())
    }
}
