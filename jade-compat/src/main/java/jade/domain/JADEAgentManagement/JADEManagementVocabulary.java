package jade.domain.JADEAgentManagement;

/** The names of JADE's agent-management ontology that concord-jade's AMS answers (see {@link JADEManagementOntology}). */
public interface JADEManagementVocabulary {
    String NAME = "JADE-Agent-Management";
    String LOCATION = "location";
    String LOCATION_NAME = "name";
    String CONTAINERID = "container-ID";
    String CONTAINERID_NAME = "name";
    String CONTAINERID_ADDRESS = "address";
    String CONTAINERID_MAIN = "main";
    String CONTAINERID_PORT = "port";
    String CONTAINERID_PROTOCOL = "protocol";
    String KILLAGENT = "kill-agent";
    String KILLAGENT_AGENT = "agent";
    String KILLAGENT_PASSWORD = "password";
    String CREATEAGENT = "create-agent";
    String CREATEAGENT_AGENT_NAME = "agent-name";
    String CREATEAGENT_CLASS_NAME = "class-name";
    String CREATEAGENT_ARGUMENTS = "arguments";
    String CREATEAGENT_CONTAINER = "container";
    String CREATEAGENT_OWNER = "owner";
    String CREATEAGENT_INITIAL_CREDENTIALS = "initial-credentials";
    String SHUTDOWNPLATFORM = "shutdown-platform";
    String QUERYAGENTSONLOCATION = "query-agents-on-location";
    String QUERYAGENTSONLOCATION_LOCATION = "location";
}
