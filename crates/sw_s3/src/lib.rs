//! A small S3-protocol client: path-style requests signed with AWS Signature Version 4,
//! over `ureq`, for any S3-compatible store (AWS S3, MinIO, moto, …). SigV4 is a page of
//! code, so the stores need no AWS SDK. Two stores sit on it: the service's package blobs
//! (`sw_store`) and the asset forge's content-addressed assets (`sw_forge`).

#[cfg(feature = "moto")]
pub mod moto;

use std::io::Read;
use std::time::{Duration, SystemTime, UNIX_EPOCH};

use sha2::{Digest, Sha256};

/// Where the bucket is and who may use it.
#[derive(Clone)]
pub struct S3Config {
    /// `http://127.0.0.1:9000` or `https://s3.eu-west-1.amazonaws.com` (no trailing slash).
    pub endpoint: String,
    pub bucket: String,
    pub region: String,
    pub access_key: String,
    pub secret_key: String,
}

impl std::fmt::Debug for S3Config {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("S3Config")
            .field("endpoint", &self.endpoint)
            .field("bucket", &self.bucket)
            .field("region", &self.region)
            .finish_non_exhaustive()
    }
}

impl S3Config {
    /// From `SCENEWRIGHT_S3_ENDPOINT`, `SCENEWRIGHT_S3_BUCKET` (default `scenewright`),
    /// `SCENEWRIGHT_S3_REGION` (default us-east-1), `AWS_ACCESS_KEY_ID` and
    /// `AWS_SECRET_ACCESS_KEY`; `None` when no endpoint is set.
    pub fn from_env() -> Option<Self> {
        let var = |k: &str| std::env::var(k).ok().filter(|v| !v.is_empty());
        let endpoint = var("SCENEWRIGHT_S3_ENDPOINT")?;
        Some(Self {
            endpoint: endpoint.trim_end_matches('/').to_string(),
            bucket: var("SCENEWRIGHT_S3_BUCKET").unwrap_or_else(|| "scenewright".into()),
            region: var("SCENEWRIGHT_S3_REGION").unwrap_or_else(|| "us-east-1".into()),
            access_key: var("AWS_ACCESS_KEY_ID").unwrap_or_default(),
            secret_key: var("AWS_SECRET_ACCESS_KEY").unwrap_or_default(),
        })
    }

    /// The same endpoint and credentials with another bucket.
    pub fn with_bucket(mut self, bucket: impl Into<String>) -> Self {
        self.bucket = bucket.into();
        self
    }
}

/// Why a request failed.
#[derive(Debug, thiserror::Error)]
pub enum S3Error {
    /// The request did not get an answer (connection refused, timeout, TLS).
    #[error("S3 {op} {target}: {message}")]
    Transport { op: &'static str, target: String, message: String },
    /// The server answered with an error status.
    #[error("S3 {op} {target}: HTTP {status}: {message}")]
    Status { op: &'static str, target: String, status: u16, message: String },
    /// The answer was not what the protocol says.
    #[error("S3 {op} {target}: unreadable answer: {message}")]
    Answer { op: &'static str, target: String, message: String },
}

/// A bucket, through signed requests.
#[derive(Debug, Clone)]
pub struct S3Client {
    config: S3Config,
    agent: ureq::Agent,
}

/// An answer: status and body.
type Answer = (u16, Vec<u8>);

impl S3Client {
    pub fn new(config: S3Config) -> Self {
        let agent: ureq::Agent = ureq::Agent::config_builder()
            .http_status_as_error(false)
            .timeout_global(Some(Duration::from_secs(60)))
            .build()
            .into();
        Self { config, agent }
    }

    pub fn config(&self) -> &S3Config {
        &self.config
    }

    /// `s3://bucket/` with the endpoint, for messages.
    pub fn describe(&self) -> String {
        format!("s3://{}/ at {}", self.config.bucket, self.config.endpoint)
    }

    /// Creates the bucket if it does not exist.
    pub fn ensure_bucket(&self) -> Result<(), S3Error> {
        let (status, body) = self.request("create bucket", "PUT", "", &[], &[])?;
        // 409 BucketAlreadyOwnedByYou / BucketAlreadyExists: fine.
        if (200..300).contains(&status) || status == 409 {
            Ok(())
        } else {
            Err(self.fail("create bucket", "", status, &body))
        }
    }

    /// Writes an object; a PUT replaces it atomically (readers see old or new bytes).
    pub fn put(&self, key: &str, data: &[u8]) -> Result<(), S3Error> {
        let (status, body) = self.request("put", "PUT", key, &[], data)?;
        if (200..300).contains(&status) { Ok(()) } else { Err(self.fail("put", key, status, &body)) }
    }

    /// Reads an object; `None` when there is no such key (a missing bucket is an error).
    pub fn get(&self, key: &str) -> Result<Option<Vec<u8>>, S3Error> {
        let (status, body) = self.request("get", "GET", key, &[], &[])?;
        match status {
            200 => Ok(Some(body)),
            404 if !String::from_utf8_lossy(&body).contains("NoSuchBucket") => Ok(None),
            s => Err(self.fail("get", key, s, &body)),
        }
    }

    /// True when the object exists (a HEAD request).
    pub fn exists(&self, key: &str) -> Result<bool, S3Error> {
        let (status, body) = self.request("head", "HEAD", key, &[], &[])?;
        match status {
            200 => Ok(true),
            404 => Ok(false),
            s => Err(self.fail("head", key, s, &body)),
        }
    }

    /// Deletes an object (deleting a missing one is not an error).
    pub fn delete(&self, key: &str) -> Result<(), S3Error> {
        let (status, body) = self.request("delete", "DELETE", key, &[], &[])?;
        if (200..300).contains(&status) || status == 404 {
            Ok(())
        } else {
            Err(self.fail("delete", key, status, &body))
        }
    }

    /// Keys under a prefix (every page of ListObjectsV2).
    pub fn list(&self, prefix: &str) -> Result<Vec<String>, S3Error> {
        let mut keys = Vec::new();
        let mut token: Option<String> = None;
        loop {
            let mut q = vec![("list-type", "2".to_string()), ("prefix", prefix.to_string())];
            if let Some(t) = &token {
                q.push(("continuation-token", t.clone()));
            }
            let (status, body) = self.request("list", "GET", "", &q, &[])?;
            if status != 200 {
                return Err(self.fail("list", prefix, status, &body));
            }
            let text = String::from_utf8_lossy(&body).into_owned();
            let doc = roxmltree::Document::parse(&text).map_err(|e| S3Error::Answer {
                op: "list",
                target: self.target(prefix),
                message: e.to_string(),
            })?;
            for n in doc.descendants().filter(|n| n.has_tag_name("Key")) {
                if let Some(k) = n.text() {
                    keys.push(k.to_string());
                }
            }
            let truncated = doc.descendants().any(|n| n.has_tag_name("IsTruncated") && n.text() == Some("true"));
            token = doc
                .descendants()
                .find(|n| n.has_tag_name("NextContinuationToken"))
                .and_then(|n| n.text())
                .map(str::to_string);
            if !truncated || token.is_none() {
                return Ok(keys);
            }
        }
    }

    fn target(&self, key: &str) -> String {
        format!("s3://{}/{key}", self.config.bucket)
    }

    fn fail(&self, op: &'static str, key: &str, status: u16, body: &[u8]) -> S3Error {
        let text = String::from_utf8_lossy(body);
        // The S3 error document's <Message>, else the start of the body.
        let message = roxmltree::Document::parse(&text)
            .ok()
            .and_then(|d| {
                d.descendants().find(|n| n.has_tag_name("Message")).and_then(|n| n.text().map(str::to_string))
            })
            .unwrap_or_else(|| text.chars().take(300).collect());
        S3Error::Status { op, target: self.target(key), status, message }
    }

    /// One signed request; `key` is empty for the bucket itself.
    fn request(
        &self,
        op: &'static str,
        method: &str,
        key: &str,
        query: &[(&str, String)],
        body: &[u8],
    ) -> Result<Answer, S3Error> {
        let c = &self.config;
        let path = if key.is_empty() {
            format!("/{}", uri_encode(&c.bucket, false))
        } else {
            format!("/{}/{}", uri_encode(&c.bucket, false), uri_encode(key, false))
        };
        let mut q: Vec<(String, String)> =
            query.iter().map(|(k, v)| (uri_encode(k, true), uri_encode(v, true))).collect();
        q.sort();
        let query_string = q.iter().map(|(k, v)| format!("{k}={v}")).collect::<Vec<_>>().join("&");
        let host = c.endpoint.split("://").nth(1).unwrap_or(&c.endpoint).split('/').next().unwrap_or("").to_string();
        let (amz_date, date) = amz_dates(SystemTime::now());
        let payload_hash = hex(&Sha256::digest(body));
        let canonical = format!(
            "{method}\n{path}\n{query_string}\nhost:{host}\nx-amz-content-sha256:{payload_hash}\nx-amz-date:{amz_date}\n\nhost;x-amz-content-sha256;x-amz-date\n{payload_hash}"
        );
        let scope = format!("{date}/{}/s3/aws4_request", c.region);
        let to_sign = format!("AWS4-HMAC-SHA256\n{amz_date}\n{scope}\n{}", hex(&Sha256::digest(canonical.as_bytes())));
        let k_date = hmac(format!("AWS4{}", c.secret_key).as_bytes(), date.as_bytes());
        let k_region = hmac(&k_date, c.region.as_bytes());
        let k_service = hmac(&k_region, b"s3");
        let k_signing = hmac(&k_service, b"aws4_request");
        let signature = hex(&hmac(&k_signing, to_sign.as_bytes()));
        let auth = format!(
            "AWS4-HMAC-SHA256 Credential={}/{scope}, SignedHeaders=host;x-amz-content-sha256;x-amz-date, Signature={signature}",
            c.access_key
        );
        let url = if query_string.is_empty() {
            format!("{}{path}", c.endpoint)
        } else {
            format!("{}{path}?{query_string}", c.endpoint)
        };
        let transport = |message: String| S3Error::Transport { op, target: self.target(key), message };
        let req = ureq::http::Request::builder()
            .method(method)
            .uri(&url)
            .header("x-amz-date", &amz_date)
            .header("x-amz-content-sha256", &payload_hash)
            .header("authorization", auth)
            .body(body.to_vec())
            .map_err(|e| transport(e.to_string()))?;
        let mut resp = self.agent.run(req).map_err(|e| transport(e.to_string()))?;
        let status = resp.status().as_u16();
        let mut out = Vec::new();
        if method != "HEAD" {
            resp.body_mut()
                .as_reader()
                .read_to_end(&mut out)
                .map_err(|e| transport(format!("reading the answer: {e}")))?;
        }
        Ok((status, out))
    }
}

/// RFC 3986 encoding as SigV4 wants it (`/` kept in paths, encoded in query values).
fn uri_encode(s: &str, encode_slash: bool) -> String {
    let mut out = String::with_capacity(s.len());
    for b in s.bytes() {
        match b {
            b'A'..=b'Z' | b'a'..=b'z' | b'0'..=b'9' | b'-' | b'_' | b'.' | b'~' => out.push(b as char),
            b'/' if !encode_slash => out.push('/'),
            _ => out.push_str(&format!("%{b:02X}")),
        }
    }
    out
}

fn hex(b: &[u8]) -> String {
    b.iter().map(|x| format!("{x:02x}")).collect()
}

fn hmac(key: &[u8], msg: &[u8]) -> Vec<u8> {
    const BLOCK: usize = 64;
    let mut k = if key.len() > BLOCK { Sha256::digest(key).to_vec() } else { key.to_vec() };
    k.resize(BLOCK, 0);
    let ipad: Vec<u8> = k.iter().map(|b| b ^ 0x36).collect();
    let opad: Vec<u8> = k.iter().map(|b| b ^ 0x5c).collect();
    let inner = Sha256::new().chain_update(&ipad).chain_update(msg).finalize();
    Sha256::new().chain_update(&opad).chain_update(inner).finalize().to_vec()
}

/// `20260102T030405Z` and `20260102` for a time.
fn amz_dates(t: SystemTime) -> (String, String) {
    let secs = t.duration_since(UNIX_EPOCH).map(|d| d.as_secs()).unwrap_or(0) as i64;
    let days = secs.div_euclid(86_400);
    let rem = secs.rem_euclid(86_400);
    // Civil date from days since 1970-01-01 (Howard Hinnant's algorithm).
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + i64::from(m <= 2);
    let date = format!("{y:04}{m:02}{d:02}");
    (format!("{date}T{:02}{:02}{:02}Z", rem / 3600, rem % 3600 / 60, rem % 60), date)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hmac_sha256_matches_rfc_4231() {
        // RFC 4231 test case 2.
        let mac = hmac(b"Jefe", b"what do ya want for nothing?");
        assert_eq!(hex(&mac), "5bdcc146bf60754e6a042426089575c75a003f089d2739839dec58b964ec3843");
    }

    #[test]
    fn dates_are_utc_calendar_dates() {
        let t = UNIX_EPOCH + Duration::from_secs(1_700_000_000);
        assert_eq!(amz_dates(t), ("20231114T221320Z".to_string(), "20231114".to_string()));
        assert_eq!(amz_dates(UNIX_EPOCH + Duration::from_secs(951_782_400)).1, "20000229");
    }

    #[test]
    fn the_signing_key_matches_aws_documentation() {
        // docs.aws.amazon.com "Examples of how to derive a signing key for Signature Version 4".
        let k_date = hmac(b"AWS4wJalrXUtnFEMI/K7MDENG+bPxRfiCYEXAMPLEKEY", b"20120215");
        let k_region = hmac(&k_date, b"us-east-1");
        let k_service = hmac(&k_region, b"iam");
        let k_signing = hmac(&k_service, b"aws4_request");
        assert_eq!(hex(&k_signing), "f4780e2d9f65fa895f9c67b32ce1baf0b0d8a43505a000a1a9e090d414db404d");
    }
}
