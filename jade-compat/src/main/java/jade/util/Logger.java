package jade.util;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.util.logging.Level;
import java.util.logging.LogManager;

/**
 * JADE's logger: a {@code java.util.logging.Logger} (its levels, {@code isLoggable}, {@code log}),
 * so a JADE project's log lines go where java.util.logging sends them (standard error by default), as on JADE.
 */
public class Logger extends java.util.logging.Logger implements jade.util.leap.Serializable {
    private static final long serialVersionUID = 1L;
    public static final Level SEVERE = Level.SEVERE;
    public static final Level WARNING = Level.WARNING;
    public static final Level INFO = Level.INFO;
    public static final Level CONFIG = Level.CONFIG;
    public static final Level FINE = Level.FINE;
    public static final Level FINER = Level.FINER;
    public static final Level FINEST = Level.FINEST;
    public static final Level ALL = Level.ALL;
    public static final Level OFF = Level.OFF;

    private Logger(String name) {
        super(name, null);
    }

    /** The logger of this name, made and registered with java.util.logging on first use. */
    public static synchronized Logger getMyLogger(String name) {
        LogManager m = LogManager.getLogManager();
        java.util.logging.Logger l = m.getLogger(name);
        if (l instanceof Logger) {
            return (Logger) l;
        }
        Logger mine = new Logger(name);
        if (!m.addLogger(mine)) {
            // Another kind of logger holds the name: ours passes its records to it.
            mine.setParent(m.getLogger(name));
        }
        return mine;
    }

    /** JADE's own loggers: the same as {@link #getMyLogger}. */
    public static synchronized Logger getJADELogger(String name) {
        return getMyLogger(name);
    }

    /** Configures java.util.logging from these properties (its own keys: {@code .level}, {@code handlers}, ...). */
    public static void initialize(jade.util.leap.Properties pp) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try {
            pp.store(out, null);
            LogManager.getLogManager().readConfiguration(new ByteArrayInputStream(out.toByteArray()));
        } catch (IOException e) {
            throw new IllegalArgumentException("cannot configure logging: " + e, e);
        }
    }

    /** A line on standard output, as JADE's {@code println}. */
    public static void println(String s) {
        System.out.println(s);
    }
}
