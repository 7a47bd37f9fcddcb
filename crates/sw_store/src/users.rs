//! Users and API keys. Passwords and keys arrive here already hashed.

use serde::Serialize;

use crate::{Result, Store, StoreError, new_id, now_ms};

/// What a user may do.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Role {
    Admin,
    User,
}

impl Role {
    pub fn as_str(self) -> &'static str {
        match self {
            Role::Admin => "admin",
            Role::User => "user",
        }
    }

    pub fn parse(s: &str) -> Option<Self> {
        match s {
            "admin" => Some(Role::Admin),
            "user" => Some(Role::User),
            _ => None,
        }
    }
}

/// A user.
#[derive(Debug, Clone, Serialize)]
pub struct User {
    pub id: String,
    pub username: String,
    #[serde(skip)]
    pub password_hash: String,
    pub role: Role,
    pub created_at: i64,
}

type UserRow = (String, String, String, String, i64);

/// The password hash of a service account: no PHC string, so no password matches it.
const SERVICE_HASH: &str = "!";

fn user(r: UserRow) -> Result<User> {
    Ok(User {
        id: r.0,
        username: r.1,
        password_hash: r.2,
        role: Role::parse(&r.3).ok_or_else(|| StoreError::Corrupt(format!("role '{}'", r.3)))?,
        created_at: r.4,
    })
}

impl Store {
    /// Creates a user. The first user of a database becomes an admin, unless `role` says
    /// otherwise explicitly. A taken name — in any case: `Alice` takes `alice` — is a
    /// [`StoreError::Conflict`].
    pub async fn create_user(&self, username: &str, password_hash: &str, role: Option<Role>) -> Result<User> {
        let id = new_id();
        let now = now_ms();
        let r = sqlx::query(
            "INSERT INTO users (id, username, password_hash, role, created_at)
             SELECT $1, $2, $3, COALESCE($4, CASE WHEN (SELECT COUNT(*) FROM users) = 0 THEN 'admin' ELSE 'user' END), $5
             WHERE NOT EXISTS (SELECT 1 FROM users WHERE lower(username) = lower($6))",
        )
        .bind(&id)
        .bind(username)
        .bind(password_hash)
        .bind(role.map(Role::as_str))
        .bind(now)
        .bind(username)
        .execute(&self.pool)
        .await;
        match r {
            Ok(done) if done.rows_affected() == 1 => {}
            Ok(_) => return Err(StoreError::Conflict(format!("the user name '{username}' is taken"))),
            Err(sqlx::Error::Database(e)) if e.is_unique_violation() => {
                return Err(StoreError::Conflict(format!("the user name '{username}' is taken")));
            }
            Err(e) => return Err(e.into()),
        }
        self.user(&id).await?.ok_or_else(|| StoreError::Corrupt(format!("user {id} vanished")))
    }

    pub async fn user(&self, id: &str) -> Result<Option<User>> {
        let r: Option<UserRow> =
            sqlx::query_as("SELECT id, username, password_hash, role, created_at FROM users WHERE id = $1")
                .bind(id)
                .fetch_optional(&self.pool)
                .await?;
        r.map(user).transpose()
    }

    /// The user of a name, whatever its case.
    pub async fn user_by_name(&self, username: &str) -> Result<Option<User>> {
        let r: Option<UserRow> = sqlx::query_as(
            "SELECT id, username, password_hash, role, created_at FROM users WHERE lower(username) = lower($1)",
        )
        .bind(username)
        .fetch_optional(&self.pool)
        .await?;
        r.map(user).transpose()
    }

    /// The service account `name` (no password: nobody can sign in as it), created the first
    /// time. A login account of that name (registered before the name was reserved) is a
    /// [`StoreError::Conflict`]: its owner would see and steer the service's jobs.
    pub async fn service_account(&self, name: &str) -> Result<User> {
        let found = match self.user_by_name(name).await? {
            Some(u) => u,
            None => match self.create_user(name, SERVICE_HASH, Some(Role::User)).await {
                Err(StoreError::Conflict(_)) => {
                    self.user_by_name(name).await?.ok_or_else(|| StoreError::Conflict(name.to_string()))?
                }
                other => other?,
            },
        };
        if found.password_hash != SERVICE_HASH {
            return Err(StoreError::Conflict(format!(
                "the user '{}' is a login account, not the service account; rename it in the database",
                found.username
            )));
        }
        Ok(found)
    }

    /// Stores an API key's hash; returns the key's id.
    pub async fn create_api_key(&self, user_id: &str, name: &str, key_hash: &str) -> Result<String> {
        let id = new_id();
        sqlx::query("INSERT INTO api_keys (id, user_id, name, key_hash, created_at) VALUES ($1, $2, $3, $4, $5)")
            .bind(&id)
            .bind(user_id)
            .bind(name)
            .bind(key_hash)
            .bind(now_ms())
            .execute(&self.pool)
            .await?;
        Ok(id)
    }

    /// A user's API keys (id, name, created at; never the key), oldest first.
    pub async fn api_keys_of(&self, user_id: &str) -> Result<Vec<(String, String, i64)>> {
        Ok(sqlx::query_as("SELECT id, name, created_at FROM api_keys WHERE user_id = $1 ORDER BY created_at, id")
            .bind(user_id)
            .fetch_all(&self.pool)
            .await?)
    }

    /// Revokes one of the user's API keys: it stops working at once. `false` when the user
    /// has no key of that id.
    pub async fn delete_api_key(&self, user_id: &str, key_id: &str) -> Result<bool> {
        let r = sqlx::query("DELETE FROM api_keys WHERE id = $1 AND user_id = $2")
            .bind(key_id)
            .bind(user_id)
            .execute(&self.pool)
            .await?;
        Ok(r.rows_affected() == 1)
    }

    /// Revokes an access token (by its `jti`) until it would have expired anyway; expired
    /// revocations are forgotten on the way.
    pub async fn revoke_token(&self, jti: &str, expires_at_ms: i64) -> Result<()> {
        let mut tx = self.pool.begin().await?;
        sqlx::query("DELETE FROM revoked_tokens WHERE expires_at < $1").bind(now_ms()).execute(&mut *tx).await?;
        sqlx::query("INSERT INTO revoked_tokens (jti, expires_at) VALUES ($1, $2) ON CONFLICT(jti) DO NOTHING")
            .bind(jti)
            .bind(expires_at_ms)
            .execute(&mut *tx)
            .await?;
        tx.commit().await?;
        Ok(())
    }

    /// True when the token of this `jti` was revoked.
    pub async fn token_revoked(&self, jti: &str) -> Result<bool> {
        let r: Option<(String,)> = sqlx::query_as("SELECT jti FROM revoked_tokens WHERE jti = $1")
            .bind(jti)
            .fetch_optional(&self.pool)
            .await?;
        Ok(r.is_some())
    }

    /// The user an API key (by its hash) belongs to.
    pub async fn user_by_api_key(&self, key_hash: &str) -> Result<Option<User>> {
        let r: Option<UserRow> = sqlx::query_as(
            "SELECT u.id, u.username, u.password_hash, u.role, u.created_at
             FROM api_keys k JOIN users u ON u.id = k.user_id WHERE k.key_hash = $1",
        )
        .bind(key_hash)
        .fetch_optional(&self.pool)
        .await?;
        r.map(user).transpose()
    }

    /// Rows in a table the tests look at (a fixed list, never a user's string).
    pub async fn count_rows(&self, table: CountedTable) -> Result<i64> {
        let sql = match table {
            CountedTable::Users => "SELECT COUNT(*) FROM users",
            CountedTable::Jobs => "SELECT COUNT(*) FROM jobs",
            CountedTable::Prompts => "SELECT COUNT(*) FROM prompts",
            CountedTable::Scenes => "SELECT COUNT(*) FROM scenes",
            CountedTable::Assets => "SELECT COUNT(*) FROM assets",
        };
        let (n,): (i64,) = sqlx::query_as(sql).fetch_one(&self.pool).await?;
        Ok(n)
    }
}

/// Tables [`Store::count_rows`] counts.
#[derive(Debug, Clone, Copy)]
pub enum CountedTable {
    Users,
    Jobs,
    Prompts,
    Scenes,
    Assets,
}
