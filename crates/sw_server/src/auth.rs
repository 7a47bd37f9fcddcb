//! Authentication: argon2id password hashes, HS256 JWT access tokens, API keys for
//! scripts (`swk_…`, stored as SHA-256), and the [`Caller`] extractor every owned route
//! takes.

use argon2::Argon2;
use argon2::password_hash::{PasswordHash, PasswordHasher, PasswordVerifier, SaltString};
use axum::extract::FromRequestParts;
use axum::http::request::Parts;
use jsonwebtoken::{Algorithm, DecodingKey, EncodingKey, Header, Validation};
use serde::{Deserialize, Serialize};
use sha2::{Digest, Sha256};
use sw_store::{Role, User, now_ms};

use crate::AppState;
use crate::error::ApiError;

/// Hashes a password with argon2id and a random salt (PHC string).
pub fn hash_password(password: &str) -> Result<String, ApiError> {
    let mut salt = [0u8; 16];
    getrandom::fill(&mut salt).map_err(ApiError::internal)?;
    let salt = SaltString::encode_b64(&salt).map_err(ApiError::internal)?;
    Argon2::default().hash_password(password.as_bytes(), &salt).map(|h| h.to_string()).map_err(ApiError::internal)
}

/// Checks a password against a stored PHC hash.
pub fn verify_password(password: &str, hash: &str) -> bool {
    PasswordHash::new(hash).is_ok_and(|h| Argon2::default().verify_password(password.as_bytes(), &h).is_ok())
}

/// A JWT's claims.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Claims {
    /// The user's id.
    pub sub: String,
    pub role: String,
    pub iat: i64,
    pub exp: i64,
    /// The token's own id: signing out revokes it (tokens made before it existed have none).
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub jti: String,
}

/// Signs and checks access tokens.
#[derive(Clone)]
pub struct Tokens {
    encoding: EncodingKey,
    decoding: DecodingKey,
    pub ttl_s: i64,
}

impl std::fmt::Debug for Tokens {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Tokens").field("ttl_s", &self.ttl_s).finish_non_exhaustive()
    }
}

impl Tokens {
    pub fn new(secret: &[u8], ttl_s: i64) -> Self {
        Self { encoding: EncodingKey::from_secret(secret), decoding: DecodingKey::from_secret(secret), ttl_s }
    }

    /// An access token for a user, valid for `ttl_s` seconds from `now_s`.
    pub fn issue_at(&self, user: &User, now_s: i64) -> Result<String, ApiError> {
        let claims = Claims {
            sub: user.id.clone(),
            role: user.role.as_str().into(),
            iat: now_s,
            exp: now_s + self.ttl_s,
            jti: sw_store::new_id(),
        };
        jsonwebtoken::encode(&Header::new(Algorithm::HS256), &claims, &self.encoding).map_err(ApiError::internal)
    }

    pub fn issue(&self, user: &User) -> Result<String, ApiError> {
        self.issue_at(user, now_ms() / 1000)
    }

    /// The claims of a valid, unexpired token.
    pub fn check(&self, token: &str) -> Result<Claims, ApiError> {
        let mut v = Validation::new(Algorithm::HS256);
        v.leeway = 0;
        v.set_required_spec_claims(&["exp", "sub"]);
        match jsonwebtoken::decode::<Claims>(token, &self.decoding, &v) {
            Ok(d) => Ok(d.claims),
            Err(e) => Err(ApiError::unauthorized(match e.kind() {
                jsonwebtoken::errors::ErrorKind::ExpiredSignature => "the access token has expired; log in again",
                jsonwebtoken::errors::ErrorKind::InvalidSignature => "the access token's signature is not valid",
                _ => "the access token is not valid",
            })),
        }
    }
}

/// A new API key: what the user is shown once, and what is stored.
pub fn new_api_key() -> (String, String) {
    let key = format!("swk_{}", sw_store::new_secret());
    let hash = api_key_hash(&key);
    (key, hash)
}

pub fn api_key_hash(key: &str) -> String {
    let d = Sha256::digest(key.as_bytes());
    d.iter().map(|b| format!("{b:02x}")).collect()
}

/// The authenticated user of a request: `Authorization: Bearer <JWT or API key>`,
/// `X-API-Key: <key>`, or — on a job's WebSocket only, which browsers cannot give headers —
/// `?token=<JWT>` in the query. A token in the query of any other request is refused: URLs
/// end up in logs and histories.
#[derive(Debug, Clone)]
pub struct Caller {
    pub user: User,
    /// The access token's claims (`None` for an API key).
    pub claims: Option<Claims>,
}

impl Caller {
    pub fn is_admin(&self) -> bool {
        self.user.role == Role::Admin
    }
}

fn credential(parts: &Parts) -> Result<String, ApiError> {
    if let Some(h) = parts.headers.get(axum::http::header::AUTHORIZATION) {
        let h = h.to_str().map_err(|_| ApiError::unauthorized("the Authorization header is not text"))?;
        let token = h
            .strip_prefix("Bearer ")
            .ok_or_else(|| ApiError::unauthorized("the Authorization header must be 'Bearer <token>'"))?;
        return Ok(token.trim().to_string());
    }
    if let Some(h) = parts.headers.get("x-api-key") {
        return h
            .to_str()
            .map(|s| s.trim().to_string())
            .map_err(|_| ApiError::unauthorized("the X-API-Key header is not text"));
    }
    if let Some(q) = parts.uri.query() {
        for pair in q.split('&') {
            if let Some(t) = pair.strip_prefix("token=") {
                if !is_websocket_route(parts) {
                    return Err(ApiError::unauthorized(
                        "a token in the URL is accepted only by a job's WebSocket; send it as Authorization: Bearer <token>",
                    ));
                }
                return Ok(t.to_string());
            }
        }
    }
    Err(ApiError::unauthorized("this needs an access token (Authorization: Bearer <token>) or an API key"))
}

/// A WebSocket handshake for a job's events (`GET /api/jobs/{id}/events`, `Upgrade: websocket`).
fn is_websocket_route(parts: &Parts) -> bool {
    let upgrade = parts
        .headers
        .get(axum::http::header::UPGRADE)
        .and_then(|v| v.to_str().ok())
        .is_some_and(|v| v.eq_ignore_ascii_case("websocket"));
    let path = parts.uri.path();
    upgrade && path.starts_with("/api/jobs/") && path.ends_with("/events")
}

impl FromRequestParts<AppState> for Caller {
    type Rejection = ApiError;

    async fn from_request_parts(parts: &mut Parts, state: &AppState) -> Result<Self, Self::Rejection> {
        let cred = credential(parts)?;
        let (user, claims) = if cred.starts_with("swk_") {
            let user = state
                .store
                .user_by_api_key(&api_key_hash(&cred))
                .await?
                .ok_or_else(|| ApiError::unauthorized("unknown or revoked API key"))?;
            (user, None)
        } else {
            let claims = state.tokens.check(&cred)?;
            if !claims.jti.is_empty() && state.store.token_revoked(&claims.jti).await? {
                return Err(ApiError::unauthorized("the access token was revoked (signed out); sign in again"));
            }
            let user = state
                .store
                .user(&claims.sub)
                .await?
                .ok_or_else(|| ApiError::unauthorized("the access token's user no longer exists"))?;
            (user, Some(claims))
        };
        tracing::Span::current().record("user", user.id.as_str());
        Ok(Caller { user, claims })
    }
}
