"""The embedded database: recipes, system parameters, users, production and alarm history.

Everything outside this package (the screens, the machine layer, the command line) uses the
data only through this package's API - ``database.Database`` and the value types and helpers
of its modules - never through SQL or ``sqlite3`` directly; ``tests/data/test_boundary.py``
checks that on the source. Modules:

* ``database``     - :class:`Database`: open/create/migrate, recipes, parameters, production,
                     alarms, users; every write one transaction.
* ``recipe``       - the Recipe model, its validation, the computed tilt, the row format.
* ``parameters``   - the catalogue of system parameters (unit, range, default, role).
* ``records``      - production records, alarm events, logged changes.
* ``users``        - roles and PIN hashing.
* ``schema``       - tables and forward migrations.
* ``exchange``     - recipe import/export, production exports.
* ``recipe_files`` - reading/writing recipe files (JSON, CSV).
* ``shifts``       - day and shift windows.
* ``backup``       - online backup and checked restore.
* ``paths``        - the default database location.

``stave db`` (in ``app.cli.db``) is this package's command line.
"""
