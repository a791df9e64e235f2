import jade.core.Agent;
import jade.core.behaviours.OneShotBehaviour;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;
import jade.wrapper.AgentController;
import jade.wrapper.ContainerController;
import jade.wrapper.StaleProxyException;

/** Creates two children from code in its own container, hears from them, kills one, waits for its goodbye. */
public class Parent extends Agent {
    @Override
    protected void setup() {
        addBehaviour(new OneShotBehaviour(this) {
            @Override
            public void action() {
                try {
                    ContainerController cc = myAgent.getContainerController();
                    AgentController first = cc.createNewAgent("child1", "Child", new Object[] {myAgent.getLocalName(), "red"});
                    first.start();
                    ACLMessage hi = myAgent.blockingReceive(MessageTemplate.MatchContent("hello from child1 red"));
                    System.out.println("parent heard: " + hi.getContent());
                    AgentController second = cc.createNewAgent("child2", "Child", new Object[] {myAgent.getLocalName(), "blue"});
                    second.start();
                    hi = myAgent.blockingReceive(MessageTemplate.MatchContent("hello from child2 blue"));
                    System.out.println("parent heard: " + hi.getContent());
                    System.out.println("controller name " + first.getName());
                    first.kill();
                    ACLMessage bye = myAgent.blockingReceive(MessageTemplate.MatchContent("bye from child1"));
                    System.out.println("parent heard: " + bye.getContent());
                    try {
                        cc.createNewAgent("child2", "Child", new Object[] {"x", "y"});
                        System.out.println("a second child2 was accepted");
                    } catch (StaleProxyException e) {
                        System.out.println("a second child2 was refused");
                    }
                    second.kill();
                    bye = myAgent.blockingReceive(MessageTemplate.MatchContent("bye from child2"));
                    System.out.println("parent heard: " + bye.getContent());
                } catch (StaleProxyException e) {
                    System.out.println("controller failed: " + e);
                }
                myAgent.doDelete();
            }
        });
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
