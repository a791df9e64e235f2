package jade.util.leap;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;

/** JADE's {@code Properties}: Java's, plus loading and storing by file name. */
public class Properties extends java.util.Properties implements Serializable {
    private static final long serialVersionUID = 1L;

    public Properties() {
    }

    /** A copy of Java properties as JADE's. */
    public static Properties toLeapProperties(java.util.Properties p) {
        Properties r = new Properties();
        r.putAll(p);
        return r;
    }

    /** Loads properties from a file. */
    public void load(String fileName) throws IOException {
        try (InputStream in = Files.newInputStream(Path.of(fileName))) {
            load(in);
        }
    }

    /** Stores the properties in a file. */
    public void store(String fileName) throws IOException {
        try (OutputStream out = Files.newOutputStream(Path.of(fileName))) {
            store(out, null);
        }
    }

    @Override
    public synchronized Object clone() {
        return super.clone();
    }
}
