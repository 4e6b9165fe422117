"""``ezmigrate check`` as a linter: static checks of legacy descriptions, code selection,
suppression comments and the machine output formats (text, JSON, SARIF, GitHub, JUnit)."""
