#!/usr/bin/env python3
"""Writes rosbag2 SQLite bags (.db3) from a JSON description, with Python's own sqlite3 module and
the tables rosbag2_storage_sqlite3 creates (schema version 3: schema, metadata, topics, messages),
so that urdfsnap's reader is checked against files it did not write. make_test_bags.mjs serialises
the messages (CDR) and calls this.
usage: write_db3.py SPEC.json
SPEC: [{"file": PATH, "topics": [[id, name, type, format]], "messages": [[topic_id, ns, hex]],
        "sql": optional statements run after (to make files that lie about their tables)}]"""
import json
import os
import sqlite3
import sys

TABLES = """
CREATE TABLE schema(schema_version INTEGER PRIMARY KEY, ros_distro TEXT NOT NULL);
CREATE TABLE metadata(id INTEGER PRIMARY KEY, metadata_version INTEGER NOT NULL,
                      metadata TEXT NOT NULL);
CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL,
                    serialization_format TEXT NOT NULL, offered_qos_profiles TEXT NOT NULL);
CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL,
                      timestamp INTEGER NOT NULL, data BLOB NOT NULL);
CREATE INDEX timestamp_idx ON messages (timestamp ASC);
INSERT INTO schema VALUES (3, 'humble');
"""

for bag in json.load(open(sys.argv[1])):
    if os.path.exists(bag["file"]):
        os.remove(bag["file"])
    db = sqlite3.connect(bag["file"])
    db.executescript(TABLES)
    db.executemany("INSERT INTO topics VALUES (?, ?, ?, ?, '')", bag["topics"])
    db.executemany("INSERT INTO messages (topic_id, timestamp, data) VALUES (?, ?, ?)",
                   [(t, ns, bytes.fromhex(data)) for t, ns, data in bag["messages"]])
    for statement in bag.get("sql", []):
        db.execute(statement)
    db.commit()
    db.close()
