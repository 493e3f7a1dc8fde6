namespace tessera { const char* versionString() { return "0.1.0"; } }
