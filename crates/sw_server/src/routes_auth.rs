//! Registration, login, API keys, the caller's identity.

use axum::Json;
use axum::extract::{Path, State};
use axum::http::StatusCode;
use serde::Deserialize;
use serde_json::{Value, json};

use crate::AppState;
use crate::auth::{Caller, hash_password, new_api_key, verify_password};
use crate::body::Body;
use crate::error::{ApiError, ApiResult};
use crate::http::ClientAddr;
use crate::throttle::client_key;

/// User names that only the service itself may hold (its accounts, e.g. the
/// `scenewright dataset --database` runs' `scenewright-dataset`), in any case.
pub const RESERVED_PREFIX: &str = "scenewright-";

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Credentials {
    username: String,
    password: String,
}

fn check_username(u: &str) -> ApiResult<()> {
    let ok_len = (3..=64).contains(&u.len());
    let ok_chars = u.chars().all(|c| c.is_ascii_alphanumeric() || matches!(c, '_' | '-' | '.'));
    if !ok_len || !ok_chars {
        return Err(ApiError::new(
            StatusCode::UNPROCESSABLE_ENTITY,
            "a user name is 3 to 64 characters of letters, digits, '_', '-' and '.'",
        ));
    }
    if u.to_ascii_lowercase().starts_with(RESERVED_PREFIX) {
        return Err(ApiError::new(
            StatusCode::UNPROCESSABLE_ENTITY,
            format!("user names beginning with '{RESERVED_PREFIX}' are reserved for the service's own accounts"),
        ));
    }
    Ok(())
}

/// `POST /api/auth/register {username, password}` → 201 the user. The first user is the
/// admin. Names are one whatever their case; a client address may register a few accounts
/// an hour (429 with `Retry-After` after that).
pub async fn register(
    State(s): State<AppState>,
    client: ClientAddr,
    Body(c): Body<Credentials>,
) -> ApiResult<(StatusCode, Json<Value>)> {
    let key = format!("register:{}", client_key(client.0));
    let l = s.auth_limits;
    s.throttle.check(&key, l.registrations_per_client, l.registration_window, "registrations from this address")?;
    check_username(&c.username)?;
    if !(8..=1024).contains(&c.password.len()) {
        return Err(ApiError::new(StatusCode::UNPROCESSABLE_ENTITY, "a password is 8 to 1024 bytes"));
    }
    let password = c.password;
    let hash = tokio::task::spawn_blocking(move || hash_password(&password)).await.map_err(ApiError::internal)??;
    let user = s.store.create_user(&c.username, &hash, None).await?;
    s.throttle.record(&key, l.registration_window);
    tracing::info!(user = %user.id, "registered");
    Ok((StatusCode::CREATED, Json(json!(user))))
}

/// `POST /api/auth/login {username, password}` → `{token, token_type, expires_in}`. After
/// a few wrong passwords for a name, or from an address, sign-ins are refused for a while
/// (429 with `Retry-After`), before the password is even checked.
pub async fn login(
    State(s): State<AppState>,
    client: ClientAddr,
    Body(c): Body<Credentials>,
) -> ApiResult<Json<Value>> {
    let wrong = || ApiError::unauthorized("wrong user name or password");
    if c.username.len() > 64 || c.password.len() > 1024 {
        return Err(wrong());
    }
    let l = s.auth_limits;
    let by_user = format!("login-user:{}", c.username.to_ascii_lowercase());
    let by_client = format!("login-client:{}", client_key(client.0));
    s.throttle.check(&by_user, l.failed_logins_per_user, l.login_window, "wrong sign-ins for this user name")?;
    s.throttle.check(&by_client, l.failed_logins_per_client, l.login_window, "wrong sign-ins from this address")?;
    let user = s.store.user_by_name(&c.username).await?;
    let (hash, user) = match user {
        Some(u) => (u.password_hash.clone(), Some(u)),
        // Spend the same time on unknown names as on known ones.
        None => (dummy_hash().to_string(), None),
    };
    let password = c.password;
    let ok =
        tokio::task::spawn_blocking(move || verify_password(&password, &hash)).await.map_err(ApiError::internal)?;
    match user {
        Some(u) if ok => {
            s.throttle.clear(&by_user);
            let token = s.tokens.issue(&u)?;
            Ok(Json(
                json!({ "token": token, "token_type": "Bearer", "expires_in": s.tokens.ttl_s, "username": u.username }),
            ))
        }
        _ => {
            s.throttle.record(&by_user, l.login_window);
            s.throttle.record(&by_client, l.login_window);
            Err(wrong())
        }
    }
}

/// `POST /api/auth/logout` → 204: the access token it was called with stops working now,
/// not when it expires.
pub async fn logout(State(s): State<AppState>, caller: Caller) -> ApiResult<StatusCode> {
    let Some(claims) = &caller.claims else {
        return Err(ApiError::unprocessable("an API key is not signed out; revoke it (DELETE /api/auth/keys/{id})"));
    };
    if claims.jti.is_empty() {
        return Err(ApiError::unprocessable("this token predates revocation; it ends when it expires"));
    }
    s.store.revoke_token(&claims.jti, claims.exp.saturating_mul(1000)).await?;
    tracing::info!(user = %caller.user.id, "signed out");
    Ok(StatusCode::NO_CONTENT)
}

/// `DELETE /api/auth/keys/{id}` → 204: the key stops working at once; 404 for a key that is
/// not the caller's.
pub async fn delete_key(State(s): State<AppState>, caller: Caller, Path(id): Path<String>) -> ApiResult<StatusCode> {
    if !sw_store::is_id(&id) || !s.store.delete_api_key(&caller.user.id, &id).await? {
        return Err(ApiError::not_found("API key"));
    }
    tracing::info!(user = %caller.user.id, key = %id, "API key revoked");
    Ok(StatusCode::NO_CONTENT)
}

/// The argon2id hash of a random password nobody knows.
fn dummy_hash() -> &'static str {
    static HASH: std::sync::OnceLock<String> = std::sync::OnceLock::new();
    HASH.get_or_init(|| hash_password(&sw_store::new_secret()).unwrap_or_default())
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct KeyRequest {
    name: String,
}

/// `POST /api/auth/keys {name}` → 201 `{id, name, key}` (the key is shown only here).
pub async fn create_key(
    State(s): State<AppState>,
    caller: Caller,
    Body(k): Body<KeyRequest>,
) -> ApiResult<(StatusCode, Json<Value>)> {
    if k.name.trim().is_empty() || k.name.len() > 200 {
        return Err(ApiError::new(StatusCode::UNPROCESSABLE_ENTITY, "a key's name is 1 to 200 bytes"));
    }
    let (key, hash) = new_api_key();
    let id = s.store.create_api_key(&caller.user.id, &k.name, &hash).await?;
    Ok((StatusCode::CREATED, Json(json!({ "id": id, "name": k.name, "key": key }))))
}

/// `GET /api/auth/keys` → the caller's keys: id, name, created (the keys themselves were
/// shown once, when made).
pub async fn list_keys(State(s): State<AppState>, caller: Caller) -> ApiResult<Json<Value>> {
    let keys = s.store.api_keys_of(&caller.user.id).await?;
    let keys: Vec<Value> =
        keys.into_iter().map(|(id, name, at)| json!({ "id": id, "name": name, "created_at": at })).collect();
    Ok(Json(json!({ "keys": keys })))
}

/// `GET /api/me` → the caller.
pub async fn me(caller: Caller) -> Json<Value> {
    Json(json!(caller.user))
}
