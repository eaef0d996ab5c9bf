-- SPDX-License-Identifier: MIT
-- Schema 1 of a .hula document (docs/formats.md "Document files").
-- Append-only: never edit a released migration; add 0002_*.sql instead.
PRAGMA application_id = 1213549633;  -- 'HULA'

-- One row: the document's own state.
CREATE TABLE document (
  id INTEGER PRIMARY KEY CHECK (id = 1),
  revision INTEGER NOT NULL CHECK (revision >= 0),
  next_label INTEGER NOT NULL CHECK (next_label >= 1),
  backend TEXT NOT NULL,
  created TEXT NOT NULL,
  tool_version TEXT NOT NULL
);

-- The current entities: the encoded state (docs/formats.md "Entity state").
CREATE TABLE entities (
  label INTEGER PRIMARY KEY CHECK (label >= 1),
  state BLOB NOT NULL
);

-- Undo steps. applied = 1: revision <= document.revision, and step_entities
-- hold the states before the step; applied = 0: redoable, and they hold the
-- states after it.
CREATE TABLE steps (
  revision INTEGER PRIMARY KEY CHECK (revision >= 1),
  name TEXT NOT NULL,
  time TEXT NOT NULL,
  applied INTEGER NOT NULL CHECK (applied IN (0, 1))
);

-- The other state of each entity a step touched (NULL: the entity does not exist then).
CREATE TABLE step_entities (
  revision INTEGER NOT NULL REFERENCES steps (revision) ON DELETE CASCADE,
  label INTEGER NOT NULL,
  state BLOB,
  PRIMARY KEY (revision, label)
) WITHOUT ROWID;

PRAGMA user_version = 1;
