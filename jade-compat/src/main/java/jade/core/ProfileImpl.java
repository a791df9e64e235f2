package jade.core;

import jade.util.leap.Properties;

import java.io.IOException;

/** JADE's profile: parameters by name (see {@link Profile} for those that mean something here). */
public class ProfileImpl extends Profile {
    /** The parameters as given. */
    protected Properties bootProps;

    public ProfileImpl(Properties props) {
        bootProps = props == null ? new Properties() : props;
    }

    /** A profile for a main container ({@code true}) or a peripheral one. */
    public ProfileImpl(boolean isMain) {
        this(new Properties());
        bootProps.setProperty(MAIN, Boolean.toString(isMain));
    }

    public ProfileImpl() {
        this(true);
    }

    /** A profile read from a properties file. */
    public ProfileImpl(String fileName) throws ProfileException {
        this(new Properties());
        try {
            bootProps.load(fileName);
        } catch (IOException e) {
            throw new ProfileException("Can't load properties: " + e.getMessage(), e);
        }
    }

    /** A profile for a container joining the main container at host:port, on a platform. */
    public ProfileImpl(String host, int port, String platformID) {
        this(host, port, platformID, true);
    }

    public ProfileImpl(String host, int port, String platformID, boolean isMain) {
        this(isMain);
        if (host != null) {
            bootProps.setProperty(MAIN_HOST, host);
        }
        if (port > 0) {
            bootProps.setProperty(MAIN_PORT, Integer.toString(port));
        }
        if (platformID != null) {
            bootProps.setProperty(PLATFORM_ID, platformID);
        }
    }

    public Properties getProperties() {
        return bootProps;
    }

    public Properties getBootProperties() {
        return bootProps;
    }

    @Override
    public void setParameter(String key, String value) {
        if (value == null) {
            bootProps.remove(key);
        } else {
            bootProps.setProperty(key, value);
        }
    }

    @Override
    public String getParameter(String key, String defaultValue) {
        return bootProps.getProperty(key, defaultValue);
    }

    @Override
    public boolean getBooleanProperty(String key, boolean defaultValue) {
        String v = bootProps.getProperty(key);
        return v == null ? defaultValue : Boolean.parseBoolean(v.trim());
    }

    @Override
    public String toString() {
        return "(Profile " + bootProps + ")";
    }
}
