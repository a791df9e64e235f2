package jade.core;

/**
 * JADE's container settings, with JADE's parameter names. concord-jade reads
 * {@link #PLATFORM_ID} (the platform's name), {@link #LOCAL_HOST}/{@link #MAIN_HOST} (the address
 * agents bind), {@link #LOCAL_PORT}/{@link #MAIN_PORT} (the first port of the agents' port
 * range) and {@link #CONTAINER_NAME}; the others have no meaning here and are ignored.
 */
public abstract class Profile {
    public static final String MAIN = "main";
    public static final String MAIN_PROTO = "proto";
    public static final String MAIN_HOST = "host";
    public static final String MAIN_PORT = "port";
    public static final String DETECT_MAIN = "detect-main";
    public static final String LOCAL_HOST = "local-host";
    public static final String PRIVILEDGE_LOGICAL_NAME = "priviledge-logical-name";
    public static final String LOCAL_PORT = "local-port";
    public static final String GUI = "gui";
    public static final String LOCAL_SERVICE_MANAGER = "backupmain";
    public static final String DUMP_OPTIONS = "dump-options";
    public static final String NO_DISPLAY = "no-display";
    public static final String OWNER = "owner";
    public static final String DEFAULT_SERVICES = "jade.core.mobility.AgentMobilityService;jade.core.event.NotificationService";
    public static final String DEFAULT_SERVICES_NOMOBILITY = "jade.core.event.NotificationService";
    public static final String PLATFORM_ID = "platform-id";
    public static final String USERAUTH_KEY = "userauth-key";
    public static final String AGENTS = "agents";
    public static final String SERVICES = "services";
    public static final String REMOTE_SERVICE_MANAGER_ADDRESSES = "smaddrs";
    public static final String MTPS = "mtps";
    public static final String NO_MTP = "nomtp";
    public static final String IMTP = "imtp";
    public static final String CONTAINER_NAME = "container-name";
    public static final String ACLCODECS = "aclcodecs";
    public static final String ACCEPT_FOREIGN_AGENTS = "accept-foreign-agents";
    public static final String STYLE_3_X = "style3-x";
    public static final String FILE_DIR = "file-dir";
    public static final String IP_VERSION = "ip-version";
    public static final int IPV4 = 4;
    public static final int IPV6 = 6;
    public static final int DEFAULT_PORT = 1099;
    public static final String LOCALHOST_CONSTANT = "localhost";
    public static final String LOOPBACK_ADDRESS_CONSTANT = "127.0.0.1";
    public static final String LEAP_IMTP = "LEAP";
    public static final String RMI_IMTP = "RMI";
    public static final String JVM = "jvm";
    public static final String J2SE = "j2se";
    public static final String PJAVA = "pjava";
    public static final String MIDP = "midp";
    public static final String ANDROID = "android";

    /** A parameter's value, or the default. */
    public abstract String getParameter(String key, String defaultValue);

    /** Sets a parameter. */
    public abstract void setParameter(String key, String value);

    /** A parameter as a boolean, or the default. */
    public abstract boolean getBooleanProperty(String key, boolean defaultValue);

    /** True if this profile is for a main container. */
    public boolean isMain() {
        return getBooleanProperty(MAIN, true);
    }
}
