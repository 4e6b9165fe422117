"""The ontology: loading (rdflib), the index of classes and properties, and prefix namespaces."""
