package jade.domain.JADEAgentManagement;

import jade.core.ContainerID;

/**
 * The AMS action that creates and starts an agent of a class in a container of this JVM, with
 * arguments (strings). Owners and credentials (JADE's security) are not supported.
 */
public class CreateAgent implements jade.content.AgentAction {
    private static final long serialVersionUID = 1L;
    private String agentName;
    private String className;
    private ContainerID container;
    private final jade.util.leap.ArrayList arguments = new jade.util.leap.ArrayList();

    public CreateAgent() {
    }

    public void setAgentName(String n) {
        agentName = n;
    }

    public String getAgentName() {
        return agentName;
    }

    public void setClassName(String n) {
        className = n;
    }

    public String getClassName() {
        return className;
    }

    public void setContainer(ContainerID c) {
        container = c;
    }

    public ContainerID getContainer() {
        return container;
    }

    public void addArguments(Object a) {
        arguments.add(a);
    }

    public jade.util.leap.Iterator getAllArguments() {
        return arguments.iterator();
    }

    public void clearAllArguments() {
        arguments.clear();
    }
}
